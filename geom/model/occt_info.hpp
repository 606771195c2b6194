#pragma once
// Which OpenCASCADE this build runs on, for `tubemesh --version` and reports.
#include <string>

namespace tubemesh::geom {

std::string occt_version();

}  // namespace tubemesh::geom
