#pragma once
// Per-face facts from the B-rep that tests and reports compare meshes against: the face's
// area (OpenCASCADE's adaptive surface integration) and whether it is flat.
//
// No OpenCASCADE header here.
#include "geom/model.hpp"

namespace tubemesh::geom {

struct FaceProperties {
    double area = 0;      // of the trimmed face
    bool planar = false;  // the underlying surface is a plane
};

// Throws tubemesh::Error when `face_id` is not one of the model's faces (1..face_count()).
FaceProperties face_properties(const Model& model, int face_id);

}  // namespace tubemesh::geom
