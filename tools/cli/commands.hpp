#pragma once
// One function per subcommand: registers it on the app and returns it with the callback that
// runs it after parsing (returning the process exit code).
#include <CLI/CLI.hpp>
#include <functional>

namespace tubemesh::cli {

struct Command {
    CLI::App* app;
    std::function<int()> run;
};

Command add_check_command(CLI::App& app);       // tubemesh check MESH
Command add_inspect_command(CLI::App& app);     // tubemesh inspect CAD
Command add_make_block_command(CLI::App& app);  // tubemesh make-block --preset|--seed|--spec -o OUT
Command add_mesh_command(CLI::App& app);        // tubemesh mesh [IN] -o OUT [--until STAGE]
Command add_make_dam_command(CLI::App& app);    // tubemesh make-dam --columns C --lifts L -o DIR
Command add_batch_command(CLI::App& app);       // tubemesh batch MANIFEST -o OUTDIR | --status | --merge
Command add_batch_worker_command(CLI::App& app);  // hidden: one block's worker process

}  // namespace tubemesh::cli
