// The tubemesh command line. Each subcommand lives in its own file; this one wires them up and
// turns errors into one line on stderr with exit code 2.
#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <signal.h>

#include <exception>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/io/temporary_files.hpp"
#include "geom/model/occt_info.hpp"
#include "tools/cli/commands.hpp"
#include "job/process_memory.hpp"

int main(int argc, char** argv) {
    namespace cli = tubemesh::cli;
    // Ctrl-C, kill or timeout: remove this run's temporaries. A file-size limit (ulimit -f):
    // let the write fail with an error that names the file instead of killing the process.
    tubemesh::io::remove_temporaries_on_signals();
    tubemesh::job::return_large_blocks_when_freed();
    signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"tubemesh: conforming hex/pyramid/tet meshes for solids with tubular holes"};
    app.require_subcommand(0, 1);
    bool version = false;
    app.add_flag("--version", version, "Print the version and the library versions, then exit");

    const std::vector<cli::Command> commands = {
        cli::add_check_command(app),
        cli::add_inspect_command(app),
        cli::add_make_block_command(app),
        cli::add_mesh_command(app),
        cli::add_make_dam_command(app),
        cli::add_batch_command(app),
        cli::add_batch_worker_command(app),
    };

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help exits 0; bad arguments are usage errors: one line on stderr, exit 2.
        if (e.get_exit_code() == 0) return app.exit(e);
        fmt::print(stderr, "tubemesh: {}\n", e.what());
        return 2;
    }
    try {
        if (version) {
            fmt::print("tubemesh {} (OpenCASCADE {})\n", TUBEMESH_VERSION, tubemesh::geom::occt_version());
            return 0;
        }
        for (const cli::Command& c : commands)
            if (c.app->parsed()) return c.run();
        fmt::print("{}", app.help());
        return 0;
    } catch (const tubemesh::Error& e) {
        fmt::print(stderr, "tubemesh: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "tubemesh: internal error: {}\n", e.what());
        return 2;
    }
}
