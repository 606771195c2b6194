// `mpirun -np N tubemesh-mpi batch MANIFEST -o OUTDIR [--threads-per-block T] [--formats LIST]
// [--time-limit S] [--verbose] [--quiet]`: the batch of `tubemesh batch` across MPI ranks.
// Rank 0 reads the manifest, keeps the catalogue (the only writer) and deals blocks largest
// first, one at a time, to whichever rank is free, itself included; every rank meshes its block
// in a worker process. Same files, same catalogue as `tubemesh batch`; resumable the same way.
//
// Exit status (rank 0's, which mpirun passes on): 0 every block done, 1 some failed, 2 the
// manifest or the command line is wrong.
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <string>

#include "batch/batch_command.hpp"
#include "batch/worker.hpp"
#include "engine/core/types.hpp"
#include "tools/mpi/mpi_executor.hpp"
#include "job/process_memory.hpp"

namespace {

using namespace tubemesh;

int run_root(int argc, char** argv, int ranks, int node_share, const batch::WorkerCommand& worker) {
    CLI::App app{"tubemesh-mpi: tubemesh batch across MPI ranks"};
    app.require_subcommand(1, 1);
    CLI::App* cmd = app.add_subcommand("batch", "Mesh every block of a batch manifest across the MPI ranks");
    batch::BatchCommand c;
    int threads = 0;
    cmd->add_option("MANIFEST", c.manifest, "The batch manifest (JSON; `tubemesh make-dam` writes one)")->required();
    cmd->add_option("-o,--output", c.outdir, "Folder for the meshes, reports and the catalogue")->required();
    cmd->add_option("--threads-per-block", threads,
                    "Threads of each block (default: the node's cores over the ranks on the node)")
        ->check(CLI::Range(1, 4096));
    cmd->add_option("--formats", c.formats, "Mesh formats for every block: msh, vtu, inp (default: the manifest's)")
        ->delimiter(',');
    cmd->add_option("--time-limit", c.time_limit, "Seconds a block may take (default: the manifest's, else 3600; 0: none)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--verbose", c.verbose, "A line per block as it ends");
    cmd->add_flag("--quiet", c.quiet, "Print nothing but errors");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        fmt::print(stderr, "tubemesh-mpi: {}\n", e.what());
        return 2;
    }
    const int per_block = threads > 0 ? threads : node_share;
    return batch::run_batch_command(c, [&](std::size_t) {
        return batch::ExecutorChoice{
            std::make_unique<mpi::MpiExecutor>(worker, ranks, per_block),
            fmt::format("{} MPI rank{}, {} thread{} per block", ranks, ranks == 1 ? "" : "s", per_block,
                        per_block == 1 ? "" : "s")};
    });
}

}  // namespace

int main(int argc, char** argv) {
    tubemesh::job::return_large_blocks_when_freed();
    // A block's worker process: this program again, without MPI.
    if (argc == 2 && std::string(argv[1]) == "batch-worker") return batch::worker_main();

    MPI_Init(&argc, &argv);
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const int node_share = mpi::node_share_of_cores();
    int code = 0;
    try {
        const batch::WorkerCommand worker{batch::self_program(), {"batch-worker"}};
        if (rank == 0) {
            try {
                code = run_root(argc, argv, ranks, node_share, worker);
            } catch (...) {
                mpi::stop_ranks(ranks);
                throw;
            }
            mpi::stop_ranks(ranks);
        } else {
            mpi::serve_rank(worker);
        }
    } catch (const Error& e) {
        fmt::print(stderr, "tubemesh-mpi: {}\n", e.what());
        code = 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "tubemesh-mpi: internal error: {}\n", e.what());
        code = 2;
    }
    MPI_Finalize();
    return code;
}
