#pragma once
// How a run uses the machine: resolved once, at the entry of a run (resolve_parallelism), and
// passed to every phase that runs in parallel. No phase resolves it again or keeps a copy in its
// options; oneTBB's limit is set in one place (limit_threads), around the whole run.
#include <tbb/global_control.h>

#include <optional>

namespace tubemesh {

struct Parallelism {
    // oneTBB workers of the run, at least 1 and at most the usable cores.
    unsigned threads = 1;
    // Spatial parts of the Delaunay kernel's parallel passes, at least 1. The mesh is a function
    // of the input and this count only, so it is the same for any thread count.
    unsigned parts = 2;
};

// The cores this process may use (its CPU affinity), at least 1.
int usable_cores();

// The parallelism a user asked for: `threads` workers (0: all usable cores; more than the cores
// are capped, since they only add start-up and contention) and `parts` Delaunay parts (0: one
// per thread, the mesh then depends on the thread count). A negative thread count is an Error.
Parallelism resolve_parallelism(int threads, unsigned parts);

// oneTBB's limit of par.threads workers for as long as the result lives (nested limits take the
// smallest). Empty when par.threads is all the usable cores: oneTBB's default already is.
std::optional<tbb::global_control> limit_threads(const Parallelism& par);

}  // namespace tubemesh
