#pragma once
// The model's side of MeshDescription: the length unit, each surface group's B-rep surface
// kind, and an alias that says where a face is: its name in the file, or on a built block its
// side (geom/model/face_names.hpp).
//
// No OpenCASCADE header here.
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/mesh_description.hpp"
#include "geom/model/model.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// Fills description.length_unit and description.surface_groups for the groups of `mesh`
// ("face_<id>" and "pipe_<k>", k-th tube of `tubes`); other groups get no entry.
void describe_groups(const Model& model, const TubeSearch& tubes, const HybridMesh& mesh,
                     MeshDescription& description);

}  // namespace tubemesh::geom
