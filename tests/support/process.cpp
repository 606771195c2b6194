#include "tests/support/process.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

namespace tubemesh::testing {

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TempDir::TempDir() {
    std::random_device rd;
    for (int attempt = 0; attempt < 100; ++attempt) {
        fs::path p = fs::temp_directory_path() /
                     ("tubemesh-test-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
        if (fs::create_directory(p)) {
            path_ = p;
            return;
        }
    }
    throw std::runtime_error("cannot create a temporary directory");
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

ProcessResult run_command(const std::string& command_line) {
    TempDir dir;
    const fs::path out = dir / "stdout", err = dir / "stderr";
    const std::string full =
        command_line + " </dev/null >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
    const int status = std::system(full.c_str());
    ProcessResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

SignalledRun signal_when_created(const std::vector<std::string>& argv, const fs::path& dir, const std::string& prefix,
                                 int signal_number) {
    constexpr uint32_t kEvents = IN_CREATE | IN_MOVED_TO;
    const int watch = inotify_init1(IN_CLOEXEC);
    const int top = watch < 0 ? -1 : inotify_add_watch(watch, dir.c_str(), kEvents);
    if (top < 0) throw std::runtime_error("inotify failed");
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t child = fork();
    if (child < 0) throw std::runtime_error("fork failed");
    if (child == 0) {
        execv(args[0], args.data());
        _exit(127);
    }
    // The child's end wakes the poll too, so a run that never makes the entry does not hang it.
    const int ended = static_cast<int>(syscall(SYS_pidfd_open, child, 0));
    SignalledRun run;
    alignas(inotify_event) char buffer[4096];
    while (!run.sent) {
        pollfd fds[2] = {{watch, POLLIN, 0}, {ended, POLLIN, 0}};
        if (poll(fds, ended >= 0 ? 2 : 1, -1) < 0) break;
        if (!(fds[0].revents & POLLIN)) break;  // the child ended
        const ssize_t n = read(watch, buffer, sizeof buffer);
        if (n <= 0) break;
        for (char* p = buffer; p < buffer + n && !run.sent;) {
            const auto* e = reinterpret_cast<const inotify_event*>(p);
            const std::string name = e->len > 0 ? e->name : "";
            if (name.rfind(prefix, 0) == 0) {
                run.sent = kill(child, signal_number) == 0;
            } else if (e->wd == top && (e->mask & IN_ISDIR) && (e->mask & IN_CREATE)) {
                inotify_add_watch(watch, (dir / name).c_str(), kEvents);
            }
            p += sizeof(inotify_event) + e->len;
        }
    }
    close(watch);
    if (ended >= 0) close(ended);
    waitpid(child, &run.status, 0);
    return run;
}

}  // namespace tubemesh::testing
