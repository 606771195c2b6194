#pragma once
// The names the CLI tests call unqualified: JSON, the program under test, shell quoting, running a
// command line, temporary folders and std::filesystem as fs. For test sources only: it puts them
// into namespace tubemesh, where the tests live.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace tubemesh {

using nlohmann::json;
using testing::cli;
using testing::q;
using testing::run_command;
using testing::TempDir;
namespace fs = std::filesystem;

}  // namespace tubemesh
