#include "python/interrupt.hpp"

namespace tubemesh::python {

namespace py = pybind11;

namespace {
// Often enough for Ctrl-C to feel immediate, rarely enough that taking the GIL costs nothing.
constexpr std::chrono::milliseconds kCheckEvery{20};
}  // namespace

InterruptListener::InterruptListener(py::object progress)
    : progress_(std::move(progress)), caller_(std::this_thread::get_id()) {}

InterruptListener::~InterruptListener() {
    // Python objects are released with the GIL held: the destructor runs after the run, in
    // Python's thread.
    py::gil_scoped_acquire gil;
    kept_.reset();
    progress_ = py::object();
}

ProgressCallback InterruptListener::callback() {
    return [this](const ProgressEvent& e) { on_progress(e); };
}

void InterruptListener::on_progress(const ProgressEvent& event) {
    if (stopping_.load(std::memory_order_relaxed)) throw Interrupted{};
    const bool caller = std::this_thread::get_id() == caller_;
    const bool report = !progress_.is_none();
    std::unique_lock lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    const bool check = caller && now - last_check_ >= kCheckEvery;
    if (!report && !check) return;
    if (check) last_check_ = now;
    py::gil_scoped_acquire gil;
    try {
        if (report) progress_(std::string(event.phase), event.done, event.total);
        if (check && PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (py::error_already_set& e) {
        kept_.emplace(std::move(e));
        stopping_.store(true, std::memory_order_relaxed);
        throw Interrupted{};
    }
}

void InterruptListener::raise_kept_error() {
    if (!kept_) throw std::runtime_error("tubemesh: a run stopped without a Python error");
    py::error_already_set e = std::move(*kept_);
    kept_.reset();
    throw e;
}

}  // namespace tubemesh::python
