#pragma once
// The memory this process may use: the smallest of the machine's physical memory, the
// process's address-space limit (RLIMIT_AS, `ulimit -v`) and its control group's limit
// (cgroup v2 memory.max, v1 memory.limit_in_bytes). The element budget's default and
// `inspect` read it, so a run in a small container or under `ulimit -v` is refused before it
// runs out of memory, and the figure shown is the one that binds.
#include <string>

namespace tubemesh {

struct UsableMemory {
    double bytes = 0;    // 0: the system says nothing
    std::string source;  // what binds: "physical memory", "address-space limit (ulimit -v)", "cgroup limit"
};

double physical_memory_bytes();       // 0 when the system does not say
double address_space_limit_bytes();   // the soft RLIMIT_AS; 0 when unlimited
double cgroup_memory_limit_bytes();   // 0 when there is none (or none below the physical memory)

UsableMemory usable_memory();

}  // namespace tubemesh
