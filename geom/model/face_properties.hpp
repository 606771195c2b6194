#pragma once
// Per-face facts from the B-rep that tests and reports compare meshes against: the face's
// area (OpenCASCADE's adaptive surface integration) and whether it is flat.
//
// No OpenCASCADE header here.
#include <vector>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

struct FaceProperties {
    double area = 0;      // of the trimmed face
    bool planar = false;  // the underlying surface is a plane
};

// Throws tubemesh::Error when `face_id` is not one of the model's faces (1..face_count()).
FaceProperties face_properties(const Model& model, int face_id);

// The solid's volume and the total area of its faces but `skip` (ids), by the fixed-order
// integration: close enough on solids with thin B-spline pipes, where the adaptive one of
// face_properties and Model::volume is far slower (bench/results/tuning-notes.md). For estimates.
struct RoughMeasures {
    double volume = 0;
    double area = 0;
};
RoughMeasures rough_measures(const Model& model, const std::vector<int>& skip);

}  // namespace tubemesh::geom
