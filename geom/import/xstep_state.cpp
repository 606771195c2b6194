#include "geom/import/xstep_state.hpp"

#include <StepData_GlobalFactors.hxx>

namespace tubemesh::geom {

namespace {
std::mutex& xstep_mutex() {
    static std::mutex m;
    return m;
}
}  // namespace

XstepSession::XstepSession()
    : lock_(xstep_mutex()), cascade_unit_(StepData_GlobalFactors::Intance().CascadeUnit()) {}

XstepSession::~XstepSession() { StepData_GlobalFactors::Intance().SetCascadeUnit(cascade_unit_); }

}  // namespace tubemesh::geom
