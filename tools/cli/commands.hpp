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

Command add_check_command(CLI::App& app);

}  // namespace tubemesh::cli
