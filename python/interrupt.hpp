#pragma once
// Ctrl-C and Python progress callbacks during a run that has released the GIL.
//
// The pipeline reports progress through MeshOptions::progress (engine/pipeline/progress.hpp),
// from the calling thread and from oneTBB's workers. On the calling thread, at most every few
// milliseconds, the listener takes the GIL briefly and runs Python's pending signal handlers
// (PyErr_CheckSignals): Ctrl-C then raises KeyboardInterrupt there, which the listener keeps and
// turns into a C++ exception that unwinds the run (every phase is exception-safe: an error is
// how any phase stops). Back in Python, restore() raises what was kept.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <thread>

#include "engine/pipeline/progress.hpp"

namespace tubemesh::python {

// Thrown through the run when Python asked it to stop; never seen by the user.
struct Interrupted {};

class InterruptListener {
public:
    // `progress`: a Python callable (phase, done, total), or None.
    explicit InterruptListener(pybind11::object progress);
    ~InterruptListener();
    InterruptListener(const InterruptListener&) = delete;
    InterruptListener& operator=(const InterruptListener&) = delete;

    // For MeshOptions::progress. Captures this object: it must outlive the run.
    ProgressCallback callback();

    // With the GIL held, after the run threw Interrupted: raises the kept Python error.
    [[noreturn]] void raise_kept_error();

private:
    void on_progress(const ProgressEvent& event);

    pybind11::object progress_;
    std::thread::id caller_;
    std::chrono::steady_clock::time_point last_check_;
    std::mutex mutex_;  // one event into Python at a time
    std::optional<pybind11::error_already_set> kept_;
    std::atomic<bool> stopping_{false};
};

}  // namespace tubemesh::python
