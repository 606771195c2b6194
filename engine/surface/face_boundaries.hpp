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
#include "engine/sizing/field/size_field.hpp"

namespace tubemesh::surface {

// Mesh point ids of every EdgePolyline point.
struct EdgeNodes {
    std::vector<std::vector<index_t>> nodes;           // per polyline, in its point order
    std::unordered_map<index_t, index_t> polyline_of;  // B-rep edge id -> polyline index
    std::unordered_map<index_t, index_t> vertex_node;  // B-rep vertex id -> mesh point id
};

// Where an edge can be evaluated: a face that uses it and that use (the point at curve
// parameter t is surface->point(surface->edge_uv(use, t))).
struct EdgeOnFace {
    const SurfaceMap* surface = nullptr;
    EdgeUse use;
};

// Records every edge of the face's trimming loops not recorded yet, so that called face after
// face in a fixed order each edge gets the first face that uses it.
void add_edge_faces(const SurfaceMap& surface, std::unordered_map<index_t, EdgeOnFace>& out);

// The polylines, each cut again where `size` asks for shorter segments than it has (geom cuts
// edges at S, blind to the rings' finer sizes): a polyline with every segment within 1.1 times
// h(x) along it is kept as it is; any other gets N = ceil(integral of ds / t(s)) segments of
// equal share of that integral, t(s) = min(h(x(s)), length of geom's segment there), so it
// follows h near the rings and keeps geom's finer cut (a curved edge's) elsewhere. Its end
// points stay; the new points are evaluated on the face `on_face` gives for the edge. The
// result is deterministic and in the input's order.
// Throws tubemesh::Error when a polyline to cut again has no face in `on_face`.
std::vector<EdgePolyline> follow_size_field(std::span<const EdgePolyline> edges,
                                            const std::unordered_map<index_t, EdgeOnFace>& on_face,
                                            const SizeField& size);

// Size sources on edge nodes whose segments are much shorter (under 0.8 times) than h(x) there
// (a curved edge cut for its curvature, a short edge between two vertices), asking for their
// mean segment length: the faces on both sides then grade from the edge's size instead of
// meeting it with triangles of h(x). Appends to `out`.
void add_short_edge_sources(std::span<const EdgePolyline> edges, const SizeField& size, std::vector<SizeSource>& out);

// A polyline whose points are mesh nodes already: a stopped ring's wall nodes on the edge where
// the ring stops (TubeData::stops), so the face beyond meets the ring node for node.
struct FixedEdgeNodes {
    index_t edge = 0;
    std::vector<index_t> ids;  // one per polyline point, in its order
};

// Adds the points of every polyline to the mesh, each B-rep vertex once (the polylines' end
// points), in polyline order; the polylines of `fixed` edges take their given nodes instead, and
// so do their vertices wherever another polyline ends there. Throws tubemesh::Error for a
// polyline with fewer than 2 points or with points and params of different lengths, or a fixed
// one with another number of nodes.
EdgeNodes add_edge_nodes(std::span<const EdgePolyline> edges, HybridMesh& mesh,
                         std::span<const FixedEdgeNodes> fixed = {});

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
