#pragma once
// A long loop's sign of life: called on the calling thread between the steps of a long phase
// (refinement rounds, relaxation sweeps, optimisation batches), so that whoever drives the run
// hears from it often: the CLI's progress line, the Python module's Ctrl-C. It only observes (the
// mesh never depends on it) and may throw to stop the run. Empty: nobody listens.
#include <functional>

namespace tubemesh {

using Pulse = std::function<void()>;

inline void beat(const Pulse& pulse) {
    if (pulse) pulse();
}

}  // namespace tubemesh
