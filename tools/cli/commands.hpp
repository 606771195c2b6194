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

}  // namespace tubemesh::cli
