#pragma once
// Where each surface group is, measured on its boundary faces: area, centroid and the mean
// outward normal, and whether the group is flat. Names a person can use in the files and the
// report ("face_3: plane, normal +z, at z = 4").
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

struct SurfaceGroupGeometry {
    index_t faces = 0;
    double area = 0;
    Vec3 centroid{0, 0, 0};  // area-weighted
    Vec3 normal{0, 0, 0};    // unit area-weighted mean of the outward normals; 0 if they cancel
    bool flat = false;       // every face's normal within 1e-6 rad of `normal`
};

// One entry per surface group id. Triangles and quads (a quad as its two triangles 0-1-2, 0-2-3).
std::vector<SurfaceGroupGeometry> surface_group_geometry(const HybridMesh& mesh);

// The groups' node sets that meet: for each pair of surface groups that share nodes (a pipe's
// rim on its host face, the edge between two faces), the shared nodes, ascending.
struct SharedNodes {
    index_t a = 0, b = 0;  // surface group ids, a < b
    std::vector<index_t> nodes;
};
std::vector<SharedNodes> shared_group_nodes(const HybridMesh& mesh);

// The nodes of each surface group, ascending, by group id.
std::vector<std::vector<index_t>> surface_group_nodes(const HybridMesh& mesh);

}  // namespace tubemesh
