#include "tools/cli/memory_limit.hpp"

#include <sys/resource.h>

#include <algorithm>

namespace tubemesh::cli {

double limit_memory(double bytes) {
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) != 0) return 0;
    if (bytes > 0) {
        const rlim_t wanted = static_cast<rlim_t>(bytes);
        if (limit.rlim_cur == RLIM_INFINITY || wanted < limit.rlim_cur) {
            limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
            setrlimit(RLIMIT_AS, &limit);
            getrlimit(RLIMIT_AS, &limit);
        }
    }
    return limit.rlim_cur == RLIM_INFINITY ? 0 : static_cast<double>(limit.rlim_cur);
}

}  // namespace tubemesh::cli
