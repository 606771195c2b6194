#pragma once
// Writing a Model as a STEP file (AP214), for `tubemesh make-block` and round-trip tests.
#include <filesystem>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

// Writes the solid with its source's coordinates (a model held at working scale is scaled back),
// labelled with the model's length unit when STEP has a name for it (millimetre, metre,
// centimetre, inch, foot, ...), else millimetre, and
// named with the model's name when it has one (import reads it back into ImportReport::name),
// its faces with their names (geom/model/face_names.hpp: a built block's top, bottom, ...; import reads
// them back into ImportReport::face_names).
// The file appears under `path` only when complete: it is written to a temporary name in the
// same directory and renamed. Throws tubemesh::Error when the directory is not writable or
// OpenCASCADE cannot translate the shape.
void write_step(const Model& model, const std::filesystem::path& path);

}  // namespace tubemesh::geom
