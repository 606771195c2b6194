#include "engine/pipeline/thread_limit.hpp"

#include <tbb/info.h>

#include <algorithm>
#include <cstddef>

#include "engine/core/types.hpp"

namespace tubemesh {

int usable_cores() { return std::max(1, tbb::info::default_concurrency()); }

std::optional<tbb::global_control> limit_threads(int threads) {
    if (threads < 0) throw Error("the thread count must be positive (0: all cores)");
    std::optional<tbb::global_control> limit;
    if (threads > 0)
        limit.emplace(tbb::global_control::max_allowed_parallelism,
                      static_cast<std::size_t>(std::min(threads, usable_cores())));
    return limit;
}

}  // namespace tubemesh
