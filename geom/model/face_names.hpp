#pragma once
// Names that say where a model's faces are (top, bottom, upstream, downstream, left, right: +z,
// -z, -y, +y, -x, +x), beside the ids every output uses ("face_3").
//
// No OpenCASCADE header here.
#include <string>
#include <vector>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

// Per face id (index id - 1): the side of the model's bounding box a flat face lies on, its
// outward normal along that axis; empty for any other face.
std::vector<std::string> box_sides(const Model& model);

// Per face id (index id - 1): the name the source gives the face (a STEP file's, which
// write_step writes), else on a built block its box side; empty when it has none.
std::vector<std::string> face_names(const Model& model);

}  // namespace tubemesh::geom
