#pragma once
// From geometry to FaceBoundary: the mesh nodes of every discretised B-rep edge (each edge cut
// once, B-rep vertices shared, so neighbouring faces meet node for node) and, per face, its
// trimming loops rewritten as loops of those nodes, with the tubes' end loops replaced by the
// rings' outer polygons.
#include <span>
#include <unordered_map>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/surface/face_mesher.hpp"

namespace tubemesh::surface {

// Mesh point ids of every EdgePolyline point.
struct EdgeNodes {
    std::vector<std::vector<index_t>> nodes;           // per polyline, in its point order
    std::unordered_map<index_t, index_t> polyline_of;  // B-rep edge id -> polyline index
    std::unordered_map<index_t, index_t> vertex_node;  // B-rep vertex id -> mesh point id
};

// Adds the points of every polyline to the mesh, each B-rep vertex once (the polylines' end
// points), in polyline order. Throws tubemesh::Error for a polyline with fewer than 2 points
// or with points and params of different lengths.
EdgeNodes add_edge_nodes(std::span<const EdgePolyline> edges, HybridMesh& mesh);

// A ring's outer polygon on its host face (engine/sweep's RingEnd): the hole to keep free.
struct HolePolygon {
    std::span<const index_t> nodes;  // mesh point ids
    std::span<const Uv> uv;          // on the host's SurfaceMap
};

// The boundary of one face for mesh_surfaces. Each trimming loop becomes its edges' shared
// nodes (uv from each edge use's own uv curve, so a seam's two sides get their own uv). A loop
// made only of tube end loop edges is dropped: the ring covering that end brings its outer
// polygon as a hole instead. A degenerate edge (a cone's apex: no polyline and not a tube edge)
// contributes its uv samples as further occurrences of the vertex it collapses to.
// max_step: spacing of the trimming loops' uv samples (only degenerate edges use them).
// Throws tubemesh::Error when an edge of the face has neither a polyline nor a degenerate shape.
FaceBoundary face_boundary(const SurfaceMap& surface, std::span<const EdgePolyline> edges,
                           const EdgeNodes& edge_nodes, std::span<const index_t> tube_loop_edges,
                           std::span<const HolePolygon> rings, const HybridMesh& mesh, double max_step);

}  // namespace tubemesh::surface
