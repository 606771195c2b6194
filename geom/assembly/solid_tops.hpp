#pragma once
// Each assembly solid's top as a surface of its own region, for construction in lifts: the
// solid's element set is what *MODEL CHANGE removes and adds, its top what the film of an
// exposed lift acts on. No OpenCASCADE header here.
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/mesh_description.hpp"
#include "geom/assembly/assembly.hpp"

namespace tubemesh::geom {

// Adds "<solid>_top" to description.region_surfaces for every solid with flat faces on the top
// of its bounding box (outward normal +z): the surface groups of those faces, "face_<id>" or,
// where the solid above shares them, "joint_<A>_<B>" (only when every face of that joint is
// the solid's top). `mesh` is the assembly's, region k solid k.
void describe_solid_tops(const Assembly& assembly, const HybridMesh& mesh, MeshDescription& description);

}  // namespace tubemesh::geom
