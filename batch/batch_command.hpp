#pragma once
// `batch MANIFEST -o OUTDIR` as both front ends run it (`tubemesh batch` with worker
// processes on this machine, `tubemesh-mpi batch` with MPI ranks): read the manifest, take the
// output folder's lock and catalogue, run the blocks on the executor the front end makes,
// show progress and the summary. Returns the exit code: 0 every block done, 1 some failed.
// Throws tubemesh::Error (exit 2) for a wrong manifest or command line.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "batch/scheduler.hpp"

namespace tubemesh::batch {

struct BatchCommand {
    std::string manifest;
    std::string outdir;
    std::vector<std::string> formats;  // empty: the manifest's
    double time_limit = -1;            // negative: the manifest's
    std::string shard;                 // "I/N" or empty
    bool verbose = false;
    bool quiet = false;
};

// Makes the executor once the number of blocks left to mesh is known, and says how it runs
// them ("2 side by side, 1 thread each").
struct ExecutorChoice {
    std::unique_ptr<Executor> executor;
    std::string description;
};
using MakeExecutor = std::function<ExecutorChoice(std::size_t blocks_to_mesh)>;

int run_batch_command(const BatchCommand& command, const MakeExecutor& make_executor);

// This program's own path, to start workers from.
std::string self_program();

}  // namespace tubemesh::batch
