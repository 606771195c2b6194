#pragma once
// First step of meshing a face: the constrained Delaunay triangulation (in the surface metric)
// of its boundary nodes, with every boundary segment an edge and every triangle flagged inside
// or outside the face. Internal to engine/surface.
#include <vector>

#include "engine/surface/face_mesher.hpp"
#include "engine/surface/uv_insertion.hpp"
#include "engine/surface/uv_mesh.hpp"

namespace tubemesh::surface {

struct BoundaryScratch {
    std::vector<index_t> loop_vertex;  // uv vertex of each loop entry
    std::vector<std::pair<index_t, index_t>> crossing;  // edges crossing a segment to recover
    std::vector<index_t> queue;
};

// Clears `mesh` and builds the triangulation. Vertices 0-3 are the corners of a box around the
// face's uv extent; the boundary's occurrences follow, so boundary vertices are [4, first
// interior vertex). mesh.node of a boundary vertex is its FaceBoundary node index.
// Throws tubemesh::Error when a segment cannot be recovered (loops cross) or two different
// nodes share a uv.
void triangulate_boundary(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
                          UvMesh& mesh, Inserter& inserter, BoundaryScratch& scratch);

}  // namespace tubemesh::surface
