#pragma once
// OpenCASCADE's STEP translator keeps its units in process-wide state: the write.step.unit
// parameter and StepData_GlobalFactors' cascade unit, which a reader or writer sets from its own
// model and leaves behind (a STEP write in metres made the next read scale by 1000). Every STEP
// read or write in tubemesh holds this lock and puts the state back. geom/ only.
#include <mutex>

namespace tubemesh::geom {

class XstepSession {
public:
    XstepSession();   // locks, remembers the cascade unit
    ~XstepSession();  // restores it, unlocks
    XstepSession(const XstepSession&) = delete;
    XstepSession& operator=(const XstepSession&) = delete;

private:
    std::lock_guard<std::mutex> lock_;
    double cascade_unit_;
};

}  // namespace tubemesh::geom
