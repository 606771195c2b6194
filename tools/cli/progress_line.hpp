#pragma once
// The CLI's progress display for tubemesh mesh (engine/pipeline/progress.hpp events).
//  * Terminal (isatty(stderr)): one line on stderr per phase, rewritten in place
//    ("sweep      12/40  0.8 s  ETA 1.9 s") and left standing when the phase ends.
//  * Not a terminal: one plain line on stdout per finished phase ("progress: sweep 40/40 in
//    0.812 s"), so logs stay readable and stderr holds only warnings and errors.
//  * Quiet: nothing.

#include <string>

#include "engine/core/timing.hpp"
#include "engine/pipeline/progress.hpp"

namespace tubemesh::cli {

class ProgressLine {
public:
    enum class Mode { Terminal, Plain, Quiet };
    explicit ProgressLine(Mode mode) : mode_(mode) {}
    static Mode mode_for(bool quiet);  // Quiet, or Terminal when stderr is a terminal, else Plain

    void operator()(const ProgressEvent& e);
    // Ends a half-drawn terminal line (before an error or the report is printed).
    void close();
    ProgressCallback callback();  // refers to this object

private:
    Mode mode_;
    std::string phase_;
    Clock::time_point start_;
    bool open_ = false;
};

}  // namespace tubemesh::cli
