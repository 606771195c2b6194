#pragma once
// Runs a command line through the shell and captures exit code, stdout and stderr: the CLI
// tests check all three.
#include <filesystem>
#include <string>

namespace tubemesh::testing {

struct ProcessResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

ProcessResult run_command(const std::string& command_line);

// A fresh, empty directory under the system temp dir, removed by the destructor.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

// Wraps a path in single quotes for the shell.
std::string shell_quote(const std::string& s);

}  // namespace tubemesh::testing
