#include "engine/core/usable_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

namespace tubemesh {

namespace {

// A limit file's number; 0 for "max", a missing file or anything else.
double limit_in(const std::string& path) {
    std::ifstream in(path);
    std::string word;
    if (!(in >> word) || word.empty() || word.find_first_not_of("0123456789") != std::string::npos) return 0;
    return std::stod(word);
}

// The process's cgroup v2 path ("0::/a/b" in /proc/self/cgroup), "" when there is none.
std::string cgroup_v2_path() {
    std::ifstream in("/proc/self/cgroup");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("0::", 0) == 0) return line.substr(3);
    return "";
}

}  // namespace

double physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? double(pages) * double(page) : 0;
}

double address_space_limit_bytes() {
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 0;
    return static_cast<double>(limit.rlim_cur);
}

double cgroup_memory_limit_bytes() {
    double least = INFINITY;
    const auto take = [&](double bytes) {
        if (bytes > 0) least = std::min(least, bytes);
    };
    // v2: the limit of the process's group and of every group above it.
    std::string group = cgroup_v2_path();
    for (;;) {
        take(limit_in("/sys/fs/cgroup" + (group == "/" ? std::string() : group) + "/memory.max"));
        const std::size_t slash = group.find_last_of('/');
        if (group.empty() || group == "/" || slash == std::string::npos) break;
        group = slash == 0 ? "/" : group.substr(0, slash);
    }
    // v1: the group's limit as the container sees it; "no limit" reads as a number near 2^63.
    take(limit_in("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    const double physical = physical_memory_bytes();
    return std::isfinite(least) && (physical <= 0 || least < physical) ? least : 0;
}

UsableMemory usable_memory() {
    UsableMemory m{physical_memory_bytes(), "physical memory"};
    const auto lower = [&](double bytes, const char* source) {
        if (bytes > 0 && (m.bytes <= 0 || bytes < m.bytes)) m = {bytes, source};
    };
    lower(cgroup_memory_limit_bytes(), "cgroup limit");
    lower(address_space_limit_bytes(), "address-space limit (ulimit -v)");
    return m;
}

}  // namespace tubemesh
