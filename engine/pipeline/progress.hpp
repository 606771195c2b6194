#pragma once
// Progress of a long run, reported to whoever drives it (the CLI's progress line).
//
// A phase reports "done of total" items through a ProgressCallback: once at its start
// (0 of total), as it goes when it can, and once at its end (total of total). The callback
// only observes: the mesh never depends on whether, when or how often it is called.
//
// PhaseProgress is what a phase uses from parallel code: advance() is a relaxed atomic add
// and, at most about 100 times per phase, a try-lock; the callback is never called by two
// threads at once and the `done` values it sees never shrink (a pulse repeats the last one).
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>

#include "engine/core/timing.hpp"

namespace tubemesh {

struct ProgressEvent {
    std::string_view phase;  // "sweep", "surface", "pyramids", ... (PhaseReport::name)
    std::uint64_t done = 0;
    std::uint64_t total = 0;  // 0: the phase does not know how many items it has
};

// An empty function means nobody listens. It may throw to stop the run (the Python module does
// on Ctrl-C): the exception leaves the phase like the phase's own errors do (oneTBB carries it
// out of parallel loops) and the run makes no result.
using ProgressCallback = std::function<void(const ProgressEvent&)>;

class PhaseProgress {
public:
    // Reports 0 of total. `callback` may be empty; it must outlive this object.
    PhaseProgress(const ProgressCallback& callback, std::string phase, std::uint64_t total);
    PhaseProgress(const PhaseProgress&) = delete;
    PhaseProgress& operator=(const PhaseProgress&) = delete;

    // Thread-safe. Reports when the count crosses the next 1% step and no other thread is
    // reporting right now (a skipped report is covered by a later one or by finish()).
    void advance(std::uint64_t items = 1);
    // Reports the count so far again (the calling thread's sign of life inside a long part of a
    // phase, engine/core/pulse.hpp), at most ten times a second; done does not change.
    void pulse();
    // Reports total of total, unless advance() already did: a listener sees it once. Later
    // calls do nothing. Not called on failure, so a listener never sees a phase that threw as
    // complete.
    void finish();

private:
    void report(std::uint64_t done);

    const ProgressCallback& callback_;
    std::string phase_;
    std::uint64_t total_;
    std::uint64_t step_;
    std::atomic<std::uint64_t> done_{0};
    std::mutex mutex_;
    std::uint64_t reported_ = 0;  // guarded by mutex_
    Clock::time_point last_report_ = Clock::now();  // guarded by mutex_
    bool finished_ = false;       // guarded by mutex_
};

}  // namespace tubemesh
