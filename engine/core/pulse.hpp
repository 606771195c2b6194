#pragma once
// A long loop's sign of life: called between the steps of a long phase (refinement rounds,
// relaxation sweeps, optimisation batches, Delaunay insertions, recovered front elements), so
// that whoever drives the run hears from it often: the CLI's progress line, the Python module's
// Ctrl-C. Mostly on the calling thread; inside a parallel loop (the Delaunay kernel's parts, the
// quality measures) also on oneTBB's workers, so a listener must be thread-safe
// (PhaseProgress::pulse is). It only observes (the mesh never depends on it) and may throw to
// stop the run. Empty: nobody listens.
#include <functional>

namespace tubemesh {

using Pulse = std::function<void()>;

inline void beat(const Pulse& pulse) {
    if (pulse) pulse();
}

}  // namespace tubemesh
