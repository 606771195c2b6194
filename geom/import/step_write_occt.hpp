#pragma once
// write_step for a bare OpenCASCADE shape. geom/ only.
#include <TopoDS_Shape.hxx>

#include <filesystem>
#include <span>
#include <string>
#include <utility>

namespace tubemesh::geom {

// `length_unit` as in ImportReport::length_unit ("metre", "millimetre", ...); names STEP has no
// unit for are written as millimetre. Same guarantees as write_step(const Model&, ...).
// `names`: sub-shapes of `shape` (solids) and the name each is written under, which the
// reader gives back (CadFile::names).
using NamedShape = std::pair<TopoDS_Shape, std::string>;
void write_step_shape(const TopoDS_Shape& shape, const std::filesystem::path& path, const std::string& length_unit,
                      std::span<const NamedShape> names = {});

}  // namespace tubemesh::geom
