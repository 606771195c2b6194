#pragma once
// The lines every mesh file carries as a comment (and the report prints): the length unit, and
// for each surface group where it is - its alias on a built block, its CAD surface kind, face
// count, area, centroid and, for a flat group, its outward normal - then the region surfaces
// (an assembly solid's top) and the named node sets.
#include <string>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/mesh_description.hpp"

namespace tubemesh::io {

// Without a description: the groups' measured geometry alone, unit "not known".
std::vector<std::string> mesh_notes(const HybridMesh& mesh, const MeshDescription* description);

// "top" for a group with that alias, else "pipe wall" for a pipe_<k> group, else "".
std::string group_role(const HybridMesh& mesh, const MeshDescription* description, std::size_t group);

}  // namespace tubemesh::io
