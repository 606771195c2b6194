#include "batch/progress_display.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace tubemesh::batch {

namespace {

std::string duration(double s) {
    if (s < 120) return fmt::format("{:.0f} s", s);
    if (s < 7200) return fmt::format("{:.0f} min", s / 60);
    return fmt::format("{:.1f} h", s / 3600);
}

}  // namespace

ProgressDisplay::ProgressDisplay(bool quiet, bool verbose)
    : quiet_(quiet), verbose_(verbose && !quiet), terminal_(isatty(fileno(stderr)) != 0) {}

std::string ProgressDisplay::status(const BatchProgress& p) const {
    const int todo = p.total - p.skipped, finished = p.done + p.failed;
    std::string s = fmt::format("batch {}/{} done, {} failed, {} running", p.skipped + p.done, p.total, p.failed,
                                p.running);
    if (p.elapsed > 0) s += fmt::format(", {:.0f} elements/s", p.elements / p.elapsed);
    if (finished > 0 && finished < todo) s += ", ETA " + duration(p.elapsed / finished * (todo - finished));
    return s;
}

void ProgressDisplay::operator()(const BatchProgress& p) {
    using Event = BatchProgress::Event;
    if (quiet_) return;
    if (verbose_ && p.event == Event::Finished && p.record) {
        close();
        const BlockRecord& r = *p.record;
        if (r.status == "done")
            fmt::print("{} done: {} elements ({} hex, {} pyramid, {} tet), min tet collapse {:.3f}, {:.1f} s\n", r.id,
                       r.elements(), r.hexes, r.pyramids, r.tets, r.tet_collapse.min, r.seconds);
        else
            fmt::print("{} failed: {}\n", r.id, r.error);
    }
    if (verbose_ && p.event == Event::Retried) {
        close();
        fmt::print("{}: its worker died, dealt again\n", p.block->id);
    }
    if (verbose_ && p.event == Event::Estimating) {
        close();
        fmt::print("estimating the size of {} blocks to mesh the largest first\n", p.total - p.skipped);
    }
    if (terminal_) {
        fmt::print(stderr, "\r\033[K{}", status(p));
        open_ = true;
        std::fflush(stderr);
    } else if (p.event == Event::Finished) {
        fmt::print("progress: {}\n", status(p));
    }
    std::fflush(stdout);
}

void ProgressDisplay::close() {
    if (open_) fmt::print(stderr, "\r\033[K");
    std::fflush(stderr);
    open_ = false;
}

}  // namespace tubemesh::batch
