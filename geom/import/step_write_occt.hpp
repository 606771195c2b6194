#pragma once
// write_step for a bare OpenCASCADE shape. geom/ only.
#include <TopoDS_Shape.hxx>

#include <filesystem>
#include <string>

namespace tubemesh::geom {

// `length_unit` as in ImportReport::length_unit ("metre", "millimetre", ...); names STEP has no
// unit for are written as millimetre. Same guarantees as write_step(const Model&, ...).
void write_step_shape(const TopoDS_Shape& shape, const std::filesystem::path& path, const std::string& length_unit);

}  // namespace tubemesh::geom
