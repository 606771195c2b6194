// `tubemesh batch MANIFEST -o OUTDIR [--threads T] [--formats LIST] [--time-limit S]
// [--shard I/N] [--verbose] [--quiet]`: mesh every block of a manifest (batch/manifest.hpp),
// each in its own worker process, and keep the run's catalogue in OUTDIR. Started again with the
// same command it redoes only what is not done. `--status OUTDIR [--csv] [--html FILE]` shows a
// catalogue (and writes it as an HTML page);
// `--merge OUTDIR` joins the shards' catalogues into OUTDIR/catalogue.sqlite.
//
// Exit status: 0 every block done, 1 some failed (each recorded with its error), 2 the manifest
// or the command line is wrong (one line on stderr).
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "batch/batch_command.hpp"
#include "batch/block_options.hpp"
#include "batch/catalogue.hpp"
#include "batch/plan.hpp"
#include "batch/run_lock.hpp"
#include "batch/status.hpp"
#include "batch/status_html.hpp"
#include "job/outputs.hpp"
#include "batch/worker.hpp"
#include "engine/core/types.hpp"
#include "tools/cli/commands.hpp"

namespace tubemesh::cli {

namespace {

namespace fs = std::filesystem;

struct BatchArgs {
    batch::BatchCommand command;
    std::string status_dir;
    std::string merge_dir;
    std::string html;
    int threads = 0;
    bool csv = false;
    bool schema = false;
};

std::vector<batch::BlockRecord> rows_of(const fs::path& outdir) {
    const std::vector<fs::path> files = batch::catalogues_in(outdir);
    if (files.empty()) throw Error("no catalogue in '" + outdir.string() + "': is it a batch's output folder?");
    std::vector<batch::BlockRecord> rows;
    for (const fs::path& f : files) {
        const batch::Catalogue c(f);
        for (batch::BlockRecord& r : c.all()) rows.push_back(std::move(r));
    }
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.position < b.position; });
    batch::recheck_done_rows(rows, outdir);  // what the next run would redo is not done
    return rows;
}

int show_status(const BatchArgs& a) {
    if (!a.html.empty()) job::check_report_output(a.html, ".html", "the HTML report");
    const std::vector<batch::BlockRecord> rows = rows_of(a.status_dir);
    if (!a.html.empty()) job::write_text(a.html, batch::status_html(rows));
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
    if (!a.command.quiet) fmt::print("merged {} shard catalogues into {}\n{}", shards.size(), target.string(),
                             batch::status_text(merged.all()));
    for (const batch::BlockRecord& r : merged.all())
        if (r.status != "done") return 1;
    return 0;
}

int run(const BatchArgs& a) {
    const int cores = a.threads > 0 ? a.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return batch::run_batch_command(a.command, [&](std::size_t blocks) {
        const batch::SlotPlan slots = batch::plan_slots(cores, blocks);
        return batch::ExecutorChoice{
            std::make_unique<batch::LocalExecutor>(batch::WorkerCommand{batch::self_program(), {"batch-worker"}},
                                                   slots.slots, slots.threads),
            fmt::format("{} side by side, {} thread{} each", slots.slots, slots.threads, slots.threads == 1 ? "" : "s")};
    });
}

}  // namespace

Command add_batch_command(CLI::App& app) {
    auto args = std::make_shared<BatchArgs>();
    CLI::App* cmd = app.add_subcommand("batch", "Mesh every block of a batch manifest, resumably, with a catalogue");
    cmd->add_option("MANIFEST", args->command.manifest, "The batch manifest (JSON; `tubemesh make-dam` writes one)");
    cmd->add_option("-o,--output", args->command.outdir, "Folder for the meshes, reports and the catalogue");
    cmd->add_option("--threads", args->threads,
                    "Cores to use (default: all): blocks side by side, one thread each, when they outnumber the "
                    "cores; else the cores shared among the blocks")
        ->check(CLI::Range(1, 4096));
    cmd->add_option("--formats", args->command.formats,
                    "Files for every block: msh, vtu, inp, html (its HTML report) (default: the manifest's)")
        ->delimiter(',');
    cmd->add_option("--time-limit", args->command.time_limit,
                    "Seconds a block may take before its worker is killed and the block failed (default: the "
                    "manifest's, else 3600; 0: none)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--shard", args->command.shard,
                    "Mesh only share I of N (blocks whose manifest position is I mod N), with its own catalogue "
                    "(Slurm: --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)")
        ->option_text("I/N");
    cmd->add_option("--status", args->status_dir, "Print the summary of the catalogue in OUTDIR and exit")
        ->option_text("OUTDIR");
    cmd->add_flag("--csv", args->csv, "With --status: print the catalogue as CSV, one row per block");
    cmd->add_option("--html", args->html,
                    "With --status: also write the catalogue as one self-contained HTML page (charts per block, the "
                    "blocks' table linking each block's own report where the formats had html)")
        ->option_text("FILE.html");
    cmd->add_option("--merge", args->merge_dir, "Join the shard catalogues in OUTDIR into its catalogue.sqlite")
        ->option_text("OUTDIR");
    cmd->add_flag("--schema", args->schema,
                  "Print the options a manifest's blocks and defaults take (JSON: default, help, units, range, "
                  "choices, older names) and exit");
    cmd->add_flag("--verbose", args->command.verbose, "A line per block as it ends");
    cmd->add_flag("--quiet", args->command.quiet, "Print nothing but errors");
    cmd->footer(
        "Files per block in OUTDIR: <id>.<format> and <id>.report.json; catalogue.sqlite (SQLite; one per shard).\n"
        "Exit status: 0 every block done, 1 some failed (see --status), 2 the manifest or the command line is wrong.");

    return {cmd, [args]() -> int {
        if (args->schema) {
            fmt::print("{}\n", batch::manifest_schema().dump(2));
            return 0;
        }
        if (!args->status_dir.empty()) return show_status(*args);
        if (args->csv) throw Error("--csv goes with --status OUTDIR");
        if (!args->html.empty()) throw Error("--html goes with --status OUTDIR");
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
