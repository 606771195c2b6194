#include "engine/core/parallelism.hpp"

#include <tbb/info.h>

#include <algorithm>
#include <cstddef>

#include "engine/core/types.hpp"

namespace tubemesh {

int usable_cores() { return std::max(1, tbb::info::default_concurrency()); }

Parallelism resolve_parallelism(int threads, unsigned parts) {
    if (threads < 0) throw Error("the thread count must be positive (0: all cores)");
    Parallelism par;
    par.threads = static_cast<unsigned>(threads == 0 ? usable_cores() : std::min(threads, usable_cores()));
    par.parts = parts == 0 ? par.threads : parts;
    return par;
}

std::optional<tbb::global_control> limit_threads(const Parallelism& par) {
    std::optional<tbb::global_control> limit;
    if (par.threads < static_cast<unsigned>(usable_cores()))
        limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t{std::max(par.threads, 1u)});
    return limit;
}

}  // namespace tubemesh
