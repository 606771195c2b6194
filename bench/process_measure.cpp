#include "bench/process_measure.hpp"

#include <fcntl.h>
#include <malloc.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/timing.hpp"

extern char** environ;

namespace tubemesh::bench {

long status_kb(const char* key) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::string k = std::string(key) + ":";
    while (std::getline(in, line))
        if (line.rfind(k, 0) == 0) return std::atol(line.c_str() + k.size());
    return -1;
}

namespace {
// The resident set may grow a little between the reset and the check (page-table pages, a
// lazily touched stack page); a peak that did not come down is off by megabytes.
constexpr long kResetSlackKb = 256;
}  // namespace

bool reset_peak_rss() {
    // Freed heap pages stay resident in glibc's arenas (the CAD build, an earlier case), and
    // the next case would reuse them without raising the resident set: its peak growth would
    // read low or zero. Trimming hands every whole free page back first.
    malloc_trim(0);
    {
        std::ofstream out("/proc/self/clear_refs");
        out << "5";
        if (!out.flush()) return false;
    }
    return status_kb("VmHWM") <= status_kb("VmRSS") + kResetSlackKb;
}

namespace {
double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }
}  // namespace

double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

ProgramRun run_program(const std::vector<std::string>& argv, const std::filesystem::path& log,
                       double limit_seconds) {
    // `timeout` rather than a timer here: a peer that loops forever (TetGen's -q can, on small
    // input angles) must not hang the whole benchmark run.
    // GNU time between them for the peak: a process started from this one inherits its peak
    // resident set (Linux keeps the larger of the spawning image's and its own in ru_maxrss, so
    // every peer read at least the benchmark's own 50-200 MB: all three peers of the dam block
    // showed 207.8 MB after the serpentine lift). `time` forks the program from its own small
    // image and writes that child's peak alone.
    const std::filesystem::path rss_file = log.string() + ".maxrss";
    std::filesystem::remove(rss_file);
    std::vector<std::string> full{"timeout", std::to_string(limit_seconds), "time", "-f", "%M", "-o",
                                  rss_file.string()};
    full.insert(full.end(), argv.begin(), argv.end());
    std::vector<char*> args;
    for (std::string& a : full) args.push_back(a.data());
    args.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);

    ProgramRun run;
    const auto t0 = Clock::now();
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
        run.output = "cannot start " + full[0] + ": error " + std::to_string(spawned);
        return run;
    }
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    run.wall_seconds = seconds_since(t0);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    // time's file ends with the peak in KiB (after a "Command exited with non-zero status"
    // line when the program failed); missing when the limit stopped the run (peak 0: unknown).
    std::ifstream rss(rss_file);
    std::string line, last;
    while (std::getline(rss, line))
        if (!line.empty()) last = line;
    char* end = nullptr;
    const long peak_kb = std::strtol(last.c_str(), &end, 10);
    if (end != last.c_str() && peak_kb > 0) run.peak_rss_bytes = 1024.0 * static_cast<double>(peak_kb);
    std::filesystem::remove(rss_file);
    run.cpu_seconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    run.output = text.str();
    return run;
}

}  // namespace tubemesh::bench
