#include "geom/model/occt_info.hpp"

#include <Standard_Version.hxx>

namespace tubemesh::geom {

std::string occt_version() { return OCC_VERSION_COMPLETE; }

}  // namespace tubemesh::geom
