// `tubemesh batch MANIFEST -o OUTDIR [--threads T] [--formats LIST] [--time-limit S]
// [--shard I/N] [--verbose] [--quiet]`: mesh every block of a manifest (batch/manifest.hpp),
// each in its own worker process, and keep the run's catalogue in OUTDIR. Started again with the
// same command it redoes only what is not done. `--status OUTDIR [--csv]` shows a catalogue;
// `--merge OUTDIR` joins the shards' catalogues into OUTDIR/catalogue.sqlite.
//
// Exit status: 0 every block done, 1 some failed (each recorded with its error), 2 the manifest
// or the command line is wrong (one line on stderr).
#include <fmt/format.h>
#include <unistd.h>

#include <climits>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "batch/catalogue.hpp"
#include "batch/manifest.hpp"
#include "batch/plan.hpp"
#include "batch/run_lock.hpp"
#include "batch/scheduler.hpp"
#include "batch/status.hpp"
#include "batch/worker.hpp"
#include "engine/core/types.hpp"
#include "tools/cli/batch_progress.hpp"
#include "tools/cli/commands.hpp"

namespace tubemesh::cli {

namespace {

namespace fs = std::filesystem;

struct BatchArgs {
    std::string manifest;
    std::string outdir;
    std::string status_dir;
    std::string merge_dir;
    std::string shard;
    std::vector<std::string> formats;
    double time_limit = -1;
    int threads = 0;
    bool csv = false;
    bool verbose = false;
    bool quiet = false;
};

std::string self_program() {
    char path[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0) throw Error("batch: cannot find this program's own path to start workers");
    return std::string(path, static_cast<std::size_t>(n));
}

// "I/N" with 0 <= I < N.
std::pair<int, int> parse_shard(const std::string& s) {
    int i = -1, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || i < 0 || i >= n)
        throw Error("--shard " + s + ": use I/N with 0 <= I < N (Slurm: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)");
    return {i, n};
}

std::vector<batch::BlockRecord> rows_of(const fs::path& outdir) {
    const std::vector<fs::path> files = batch::catalogues_in(outdir);
    if (files.empty()) throw Error("no catalogue in '" + outdir.string() + "': is it a batch's output folder?");
    std::vector<batch::BlockRecord> rows;
    for (const fs::path& f : files) {
        const batch::Catalogue c(f);
        for (batch::BlockRecord& r : c.all()) rows.push_back(std::move(r));
    }
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.position < b.position; });
    return rows;
}

int show_status(const BatchArgs& a) {
    const std::vector<batch::BlockRecord> rows = rows_of(a.status_dir);
    fmt::print("{}", a.csv ? batch::status_csv(rows) : batch::status_text(rows));
    for (const batch::BlockRecord& r : rows)
        if (r.status != "done") return 1;
    return 0;
}

int merge(const BatchArgs& a) {
    const fs::path outdir = a.merge_dir;
    std::vector<fs::path> shards;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(outdir, ec)) {
        const std::string name = e.path().filename().string();
        if (name.starts_with("catalogue.shard-") && name.ends_with(".sqlite")) shards.push_back(e.path());
    }
    if (shards.empty()) throw Error("no shard catalogues (catalogue.shard-I-of-N.sqlite) in '" + outdir.string() + "'");
    std::sort(shards.begin(), shards.end());
    const fs::path target = batch::catalogue_path(outdir);
    batch::RunLock lock(target);
    batch::Catalogue merged(target);
    for (const fs::path& s : shards) merged.merge_from(s);
    if (!a.quiet) fmt::print("merged {} shard catalogues into {}\n{}", shards.size(), target.string(),
                             batch::status_text(merged.all()));
    for (const batch::BlockRecord& r : merged.all())
        if (r.status != "done") return 1;
    return 0;
}

int run(const BatchArgs& a) {
    if (a.manifest.empty()) throw Error("batch needs a MANIFEST (or --status OUTDIR, --merge OUTDIR)");
    if (a.outdir.empty()) throw Error("batch needs -o OUTDIR, the folder for the meshes and the catalogue");
    int shard = -1, shards = 0;
    if (!a.shard.empty()) std::tie(shard, shards) = parse_shard(a.shard);

    nlohmann::json overrides = nlohmann::json::object();
    if (!a.formats.empty()) overrides["formats"] = a.formats;
    if (a.time_limit >= 0) overrides["time_limit"] = a.time_limit;
    const batch::Manifest manifest = batch::read_manifest(a.manifest, overrides);  // Error -> exit 2

    const fs::path outdir = fs::absolute(a.outdir);
    std::error_code ec;
    fs::create_directories(outdir, ec);
    if (!fs::is_directory(outdir)) throw Error("cannot create the output folder '" + outdir.string() + "'");
    const fs::path catalogue_file = batch::catalogue_path(outdir, shard, shards);
    batch::RunLock lock(catalogue_file);
    batch::Catalogue catalogue(catalogue_file);

    const std::vector<const batch::BlockEntry*> blocks = batch::shard_blocks(manifest, shard, shards);
    const int threads = a.threads > 0 ? a.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // Blocks that are done need no slot: size the slots on what is left to do.
    std::size_t todo = 0;
    for (const batch::BlockEntry* b : blocks) {
        const auto row = catalogue.get(b->id);
        todo += !(row && batch::done_and_intact(*row, *b, outdir));
    }
    const batch::SlotPlan slots = batch::plan_slots(threads, todo);
    batch::LocalExecutor executor({self_program(), {"batch-worker"}}, slots.slots, slots.threads);

    auto display = std::make_shared<BatchProgressLine>(a.quiet, a.verbose);
    batch::BatchRun run;
    run.outdir = outdir;
    run.progress = [display](const batch::BatchProgress& p) { (*display)(p); };
    const batch::BatchSummary s = batch::run_blocks(executor, catalogue, blocks, run);
    display->close();

    if (!a.quiet) {
        fmt::print("{}: {} blocks{}, {} done before, {} meshed now, {} failed; {} elements in {:.1f} s ({:.0f} elements/s, "
                   "{} side by side, {} thread{} each)\n",
                   manifest.name, s.total, shards > 0 ? fmt::format(" in shard {}/{}", shard, shards) : "", s.skipped,
                   s.done, s.failed, s.elements, s.seconds, s.seconds > 0 ? s.elements / s.seconds : 0.0, slots.slots,
                   slots.threads, slots.threads == 1 ? "" : "s");
        for (const batch::BlockRecord& r : catalogue.all())
            if (r.status == "failed") fmt::print(stderr, "tubemesh: block {} failed: {}\n", r.id, r.error);
        fmt::print("catalogue: {}\n", catalogue_file.string());
    }
    for (const batch::BlockRecord& r : catalogue.all())
        if (r.status != "done") return 1;
    return 0;
}

}  // namespace

Command add_batch_command(CLI::App& app) {
    auto args = std::make_shared<BatchArgs>();
    CLI::App* cmd = app.add_subcommand("batch", "Mesh every block of a batch manifest, resumably, with a catalogue");
    cmd->add_option("MANIFEST", args->manifest, "The batch manifest (JSON; `tubemesh make-dam` writes one)");
    cmd->add_option("-o,--output", args->outdir, "Folder for the meshes, reports and the catalogue");
    cmd->add_option("--threads", args->threads,
                    "Cores to use (default: all): blocks side by side, one thread each, when they outnumber the "
                    "cores; else the cores shared among the blocks")
        ->check(CLI::Range(1, 4096));
    cmd->add_option("--formats", args->formats, "Mesh formats for every block: msh, vtu, inp (default: the manifest's)")
        ->delimiter(',');
    cmd->add_option("--time-limit", args->time_limit,
                    "Seconds a block may take before its worker is killed and the block failed (default: the "
                    "manifest's, else 3600; 0: none)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--shard", args->shard,
                    "Mesh only share I of N (blocks whose manifest position is I mod N), with its own catalogue "
                    "(Slurm: --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)")
        ->option_text("I/N");
    cmd->add_option("--status", args->status_dir, "Print the summary of the catalogue in OUTDIR and exit")
        ->option_text("OUTDIR");
    cmd->add_flag("--csv", args->csv, "With --status: print the catalogue as CSV, one row per block");
    cmd->add_option("--merge", args->merge_dir, "Join the shard catalogues in OUTDIR into its catalogue.sqlite")
        ->option_text("OUTDIR");
    cmd->add_flag("--verbose", args->verbose, "A line per block as it ends");
    cmd->add_flag("--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "Files per block in OUTDIR: <id>.<format> and <id>.report.json; catalogue.sqlite (SQLite; one per shard).\n"
        "Exit status: 0 every block done, 1 some failed (see --status), 2 the manifest or the command line is wrong.");

    return {cmd, [args]() -> int {
        if (!args->status_dir.empty()) return show_status(*args);
        if (args->csv) throw Error("--csv goes with --status OUTDIR");
        if (!args->merge_dir.empty()) return merge(*args);
        return run(*args);
    }};
}

Command add_batch_worker_command(CLI::App& app) {
    CLI::App* worker = app.add_subcommand("batch-worker", "");
    worker->group("");  // hidden: started by `tubemesh batch` itself, not by users
    return {worker, []() -> int { return batch::worker_main(); }};
}

}  // namespace tubemesh::cli
