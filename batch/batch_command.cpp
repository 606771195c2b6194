#include "batch/batch_command.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <filesystem>

#include "batch/catalogue.hpp"
#include "batch/manifest.hpp"
#include "batch/plan.hpp"
#include "batch/progress_display.hpp"
#include "batch/run_lock.hpp"
#include "engine/core/types.hpp"

namespace tubemesh::batch {

namespace {

namespace fs = std::filesystem;

// "I/N" with 0 <= I < N.
std::pair<int, int> parse_shard(const std::string& s) {
    int i = -1, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || i < 0 || i >= n)
        throw Error("--shard " + s + ": use I/N with 0 <= I < N (Slurm: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)");
    return {i, n};
}

}  // namespace

std::string self_program() {
    char path[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0) throw Error("batch: cannot find this program's own path to start workers");
    return std::string(path, static_cast<std::size_t>(n));
}

int run_batch_command(const BatchCommand& a, const MakeExecutor& make_executor) {
    if (a.manifest.empty()) throw Error("batch needs a MANIFEST");
    if (a.outdir.empty()) throw Error("batch needs -o OUTDIR, the folder for the meshes and the catalogue");
    int shard = -1, shards = 0;
    if (!a.shard.empty()) std::tie(shard, shards) = parse_shard(a.shard);

    nlohmann::json overrides = nlohmann::json::object();
    if (!a.formats.empty()) overrides["formats"] = a.formats;
    if (a.time_limit >= 0) overrides["time_limit"] = a.time_limit;
    const Manifest manifest = read_manifest(a.manifest, overrides);

    const fs::path outdir = fs::absolute(a.outdir);
    std::error_code ec;
    fs::create_directories(outdir, ec);
    if (!fs::is_directory(outdir)) throw Error("cannot create the output folder '" + outdir.string() + "'");
    const fs::path catalogue_file = catalogue_path(outdir, shard, shards);
    RunLock lock(catalogue_file);
    Catalogue catalogue(catalogue_file);

    const std::vector<const BlockEntry*> blocks = shard_blocks(manifest, shard, shards);
    // Once: the plan reads every done block's files through to check their SHA-256.
    std::vector<PlannedBlock> todo = plan_run(catalogue, blocks, outdir);
    ExecutorChoice choice = make_executor(todo.size());

    ProgressDisplay display(a.quiet, a.verbose);
    BatchRun run;
    run.outdir = outdir;
    run.progress = [&display](const BatchProgress& p) { display(p); };
    const BatchSummary s = run_blocks(*choice.executor, catalogue, blocks.size(), std::move(todo), run);
    display.close();

    const std::vector<BlockRecord> rows = catalogue.all();
    if (!a.quiet) {
        fmt::print("{}: {} blocks{}, {} done before, {} meshed now, {} failed; {} elements in {:.1f} s "
                   "({:.0f} elements/s, {})\n",
                   manifest.name, s.total, shards > 0 ? fmt::format(" in shard {}/{}", shard, shards) : "",
                   s.skipped, s.done, s.failed, s.elements, s.seconds, s.seconds > 0 ? s.elements / s.seconds : 0.0,
                   choice.description);
        for (const BlockRecord& r : rows)
            if (r.status == "failed") fmt::print(stderr, "tubemesh: block {} failed: {}\n", r.id, r.error);
        fmt::print("catalogue: {}\n", catalogue_file.string());
    }
    for (const BlockRecord& r : rows)
        if (r.status != "done") return 1;
    return 0;
}

}  // namespace tubemesh::batch
