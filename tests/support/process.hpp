#pragma once
// Runs a command line through the shell and captures exit code, stdout and stderr: the CLI
// tests check all three.
#include <filesystem>
#include <string>
#include <vector>

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

// Runs `argv` (argv[0] the program) and sends it `signal_number` as soon as an entry whose name
// starts with `prefix` is created in, or renamed into, `dir` or a folder made in `dir` while it
// runs. Waits for the program's end: `status` as waitpid gives it, `sent` whether the signal went
// (false when the program ended before such an entry appeared).
struct SignalledRun {
    int status = 0;
    bool sent = false;
};
SignalledRun signal_when_created(const std::vector<std::string>& argv, const std::filesystem::path& dir,
                                 const std::string& prefix, int signal_number);

// Wraps a path in single quotes for the shell.
std::string shell_quote(const std::string& s);

}  // namespace tubemesh::testing
