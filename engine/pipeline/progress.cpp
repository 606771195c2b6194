#include "engine/pipeline/progress.hpp"

#include <algorithm>

namespace tubemesh {

PhaseProgress::PhaseProgress(const ProgressCallback& callback, std::string phase, std::uint64_t total)
    : callback_(callback), phase_(std::move(phase)), total_(total), step_(std::max<std::uint64_t>(1, total / 100)) {
    if (callback_) callback_(ProgressEvent{phase_, 0, total_});
}

void PhaseProgress::advance(std::uint64_t items) {
    if (!callback_ || items == 0) return;
    const std::uint64_t before = done_.fetch_add(items, std::memory_order_relaxed);
    const std::uint64_t after = before + items;
    if (before / step_ == after / step_) return;  // no 1% boundary crossed: the cheap path
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    report(done_.load(std::memory_order_relaxed));
}

void PhaseProgress::pulse() {
    // Often enough for a progress line and a Ctrl-C answered within half a second, rarely
    // enough that a terminal is not redrawn for every batch of a part.
    constexpr double kPulseSeconds = 0.1;
    if (!callback_) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || finished_ || seconds_since(last_report_) < kPulseSeconds) return;
    last_report_ = Clock::now();
    callback_(ProgressEvent{phase_, reported_, total_});
}

void PhaseProgress::finish() {
    if (!callback_) return;
    std::lock_guard lock(mutex_);
    if (finished_) return;
    finished_ = true;
    // advance() may have reported the total already (the tet step's third part): a listener
    // that prints a line per completed phase would print it twice.
    if (total_ > 0 && reported_ == total_) return;
    reported_ = total_ > 0 ? total_ : done_.load(std::memory_order_relaxed);
    callback_(ProgressEvent{phase_, reported_, total_});
}

void PhaseProgress::report(std::uint64_t done) {
    // Callers hold mutex_. Counts above total (a phase that found more work) are clamped.
    if (total_ > 0) done = std::min(done, total_);
    if (finished_ || done <= reported_) return;
    reported_ = done;
    last_report_ = Clock::now();
    callback_(ProgressEvent{phase_, done, total_});
}

}  // namespace tubemesh
