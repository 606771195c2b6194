#include "batch/test_hooks.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <string>

namespace tubemesh::batch {

namespace {

// MOMENT and ARG of the variable, or empty.
std::pair<std::string, std::string> fault() {
    const char* v = std::getenv("TUBEMESH_BATCH_TEST_FAULT");
    if (!v) return {};
    const std::string s(v);
    const auto colon = s.find(':');
    if (colon == std::string::npos) return {s, ""};
    return {s.substr(0, colon), s.substr(colon + 1)};
}

[[noreturn]] void die(int signal_number) {
    ::kill(::getpid(), signal_number);
    for (;;) ::pause();
}

}  // namespace

void fault_point(std::string_view moment) {
    const auto [m, arg] = fault();
    if (m.empty() || m != moment) return;
    static std::map<std::string, int> seen;
    if (++seen[m] == std::atoi(arg.c_str())) die(SIGKILL);
}

void worker_fault_point(std::string_view moment, std::string_view block_id, int attempt) {
    const auto [m, arg] = fault();
    if (m.empty() || m != moment || arg != block_id) return;
    if (m == "start" || m == "written") {
        ::kill(::getppid(), SIGKILL);
        die(SIGKILL);
    }
    if (m == "crash") {
        const rlimit no_core{0, 0};  // a test's fault needs no core file
        ::setrlimit(RLIMIT_CORE, &no_core);
        die(SIGSEGV);
    }
    if (m == "hang")
        for (;;) ::pause();
    if (m == "die-once" && attempt == 1) die(SIGKILL);
}

}  // namespace tubemesh::batch
