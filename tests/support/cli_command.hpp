#pragma once
// The tubemesh program under test and shell-quoted paths, for the CLI tests' command lines.
// TUBEMESH_CLI (the program's path) is a compile definition of every CLI test target.
#include <filesystem>
#include <string>

#include "tests/support/process.hpp"

namespace tubemesh::testing {

inline std::string cli() { return shell_quote(TUBEMESH_CLI); }
inline std::string q(const std::filesystem::path& p) { return shell_quote(p.string()); }

}  // namespace tubemesh::testing
