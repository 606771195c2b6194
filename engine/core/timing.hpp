#pragma once
// Wall time for the run reports: one clock and one way to read it.
#include <chrono>

namespace tubemesh {

using Clock = std::chrono::steady_clock;

// Seconds from t0 until now.
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace tubemesh
