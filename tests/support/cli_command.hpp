#pragma once
// The tubemesh program under test and shell-quoted paths, for the CLI tests' command lines.
// TUBEMESH_CLI (the program's path) is a compile definition of every CLI test target.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "tests/support/process.hpp"

namespace tubemesh::testing {

inline std::string cli() { return shell_quote(TUBEMESH_CLI); }
inline std::string q(const std::filesystem::path& p) { return shell_quote(p.string()); }

// DIR/PRESET.step, built by `tubemesh make-block --preset PRESET` the first time it is asked for.
inline std::filesystem::path built_preset(const std::filesystem::path& dir, const std::string& preset) {
    const std::filesystem::path p = dir / (preset + ".step");
    if (!std::filesystem::exists(p) && run_command(cli() + " make-block --preset " + preset + " -o " + q(p)).exit_code != 0)
        throw std::runtime_error("make-block --preset " + preset + " failed");
    return p;
}

}  // namespace tubemesh::testing
