#include "tools/cli/progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace tubemesh::cli {

ProgressLine::Mode ProgressLine::mode_for(bool quiet) {
    if (quiet) return Mode::Quiet;
    return isatty(fileno(stderr)) ? Mode::Terminal : Mode::Plain;
}

ProgressCallback ProgressLine::callback() {
    return [this](const ProgressEvent& e) { (*this)(e); };
}

void ProgressLine::operator()(const ProgressEvent& e) {
    if (mode_ == Mode::Quiet) return;
    const auto now = Clock::now();
    if (e.phase != phase_) {
        close();
        phase_ = std::string(e.phase);
        start_ = now;
    }
    const double elapsed = seconds_since(start_);
    const bool done = e.total > 0 && e.done >= e.total;
    if (mode_ == Mode::Plain) {
        if (done) fmt::print("progress: {} {}/{} in {:.3f} s\n", e.phase, e.done, e.total, elapsed);
        std::fflush(stdout);
        return;
    }
    std::string eta = "ETA --";
    if (e.done > 0 && e.total > e.done) eta = fmt::format("ETA {:.1f} s", elapsed * double(e.total - e.done) / e.done);
    if (done) eta = "done";
    fmt::print(stderr, "\r\033[K{:<10} {:>8}/{:<8} {:7.2f} s  {}", e.phase, e.done, e.total, elapsed, eta);
    open_ = true;
    if (done) close();
    std::fflush(stderr);
}

void ProgressLine::close() {
    if (mode_ == Mode::Terminal && open_) fmt::print(stderr, "\n");
    open_ = false;
}

}  // namespace tubemesh::cli
