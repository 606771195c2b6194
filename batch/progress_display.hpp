#pragma once
// The batch's progress display: on a terminal one line on stderr rewritten in place ("batch
// 5/12 done, 1 failed, 2 running, 41,200 elements/s, ETA 52 s"), otherwise one plain
// "progress:" line on stdout per finished block; with verbose, a line per block as it ends;
// nothing when quiet.
#include <string>

#include "batch/scheduler.hpp"

namespace tubemesh::batch {

class ProgressDisplay {
public:
    ProgressDisplay(bool quiet, bool verbose);
    void operator()(const BatchProgress& p);
    void close();  // ends a half-drawn terminal line

private:
    std::string status(const BatchProgress& p) const;
    bool quiet_, verbose_, terminal_;
    bool open_ = false;
};

}  // namespace tubemesh::batch
