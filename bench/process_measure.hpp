#pragma once
// What the benchmarks measure besides time: this process's resident set (Linux /proc), and
// another program (a peer mesher) run to completion with its wall time and peak resident set.
#include <filesystem>
#include <string>
#include <vector>

namespace tubemesh::bench {

// A "Vm..." line of /proc/self/status ("VmRSS", "VmHWM"), in KiB; -1 when it is missing.
long status_kb(const char* key);

// Lowers the resident set to the live heap (glibc malloc_trim) and the peak (VmHWM) to that
// resident set (/proc/self/clear_refs "5"), so that the next peak minus VmRSS is the work's
// own growth, whatever ran before in this process. False when the kernel did not lower the
// peak (no clear_refs, or a kernel that ignores "5"): the growth measured after it is then
// only what exceeds earlier peaks, and callers leave their peak counters out.
bool reset_peak_rss();

// User + system CPU seconds of this process so far, all threads: against the wall time it shows
// how much of the shared machine the work got.
double process_cpu_seconds();

struct ProgramRun {
    int exit_code = -1;       // the program's exit status; 124 when the time limit stopped it
    double wall_seconds = 0;  // from spawn to exit
    double cpu_seconds = 0;   // user + system, all its threads and processes
    double peak_rss_bytes = 0;
    std::string output;  // stdout and stderr, interleaved
};

// Runs argv (argv[0] looked up in PATH, no shell) under `timeout limit_seconds` and GNU time,
// stdin from /dev/null, stdout and stderr into `log`. The peak resident set is the program's
// own (GNU time's %M; 0 when the limit stopped it); the CPU time is the program's and its
// children's (wait4).
ProgramRun run_program(const std::vector<std::string>& argv, const std::filesystem::path& log,
                       double limit_seconds);

}  // namespace tubemesh::bench
