#pragma once
// The one place a run's thread count is resolved: oneTBB's limit for its lifetime.
#include <tbb/global_control.h>

#include <optional>

namespace tubemesh {

// The cores this process may use (its CPU affinity), at least 1.
int usable_cores();

// A limit of `threads` workers, capped at usable_cores(): more threads than cores only add
// start-up and contention (4096 on 2 cores turned a 0.2 s job into 78 s). 0: no limit (all
// cores). A negative count is an Error.
std::optional<tbb::global_control> limit_threads(int threads);

}  // namespace tubemesh
