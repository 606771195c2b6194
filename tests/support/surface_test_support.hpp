#pragma once
// Boundaries and checks for the surface mesher's tests: loops discretised by a size field on
// analytic faces, per-face measurements (angles, area, distance to the surface, boundary kept,
// neighbour size ratio, orientation) and closed-surface checks on a mesh store (watertight,
// manifold, oriented, free of self-intersection by the exact predicates).
#include <span>
#include <string>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/surface/face_mesher.hpp"
#include "engine/sizing/field/size_field.hpp"
#include "tests/support/surface_test_surfaces.hpp"

namespace tubemesh::testing {

// With TUBEMESH_SURFACE_DUMP=dir set, writes a face mesh to dir/name.txt for looking at it:
// "V x y z", "U u v" per node, "T a b c" per triangle, "B boundary-node-count". Does nothing
// without the variable.
void dump_face(const surface::FaceMesh& m, const surface::FaceBoundary& b, const std::string& name);

// Builds a face boundary: sides are straight in uv and cut by the size field (arc length in
// space over the local size); nodes at one position in space (a seam's two sides, loop
// corners) are merged into one boundary node.
class BoundaryBuilder {
public:
    BoundaryBuilder(const SurfaceMap& surface, const SizeField& size) : surface_(surface), size_(size) {}

    // A closed loop through the uv corners, each side cut by the size field.
    void add_loop(std::span<const Uv> corners);
    // A closed loop through exactly these uv points (a ring's outer polygon).
    void add_polygon(std::span<const Uv> points);
    // The points a side from a to b (a included, b not) would get.
    std::vector<Uv> cut_side(Uv a, Uv b) const;

    const surface::FaceBoundary& boundary() const { return b_; }
    surface::FaceBoundary take() { return std::move(b_); }

private:
    index_t node_at(Uv p);
    const SurfaceMap& surface_;
    const SizeField& size_;
    surface::FaceBoundary b_;
};

// A regular n-gon of "radius" rho around c in uv (counter-clockwise), first point at angle a0.
std::vector<Uv> uv_polygon(Uv c, double rho, int n, double a0 = 0);
// An n-gon that is (to first order) regular in space, of radius rho, around uv c: what a
// ring's outer polygon looks like in its host face's parameters.
std::vector<Uv> round_polygon(const SurfaceMap& surface, Uv c, double rho, int n, double a0 = 0);
// Size sources for polygons given in uv on a surface.
void add_uv_polygon_sources(const SurfaceMap& surface, std::span<const Uv> polygon, std::vector<SizeSource>& out);

struct FaceReport {
    index_t triangles = 0;
    double min_angle = 0;           // degrees
    double max_angle = 0;           // degrees
    double fraction_above_40 = 0;   // triangles whose angles are all >= 40 degrees
    double area = 0;
    double max_distance = 0;        // of nodes from the surface, over the local size
    double max_neighbor_ratio = 0;  // mean edge length ratio across interior edges
    index_t pairs = 0, pairs_above_1_4 = 0, pairs_above_1_5 = 0;  // interior edges, by that ratio
    double max_edge = 0;
    std::vector<std::string> problems;  // broken invariants, empty when all hold
};

// Measures one face mesh and checks its invariants: boundary nodes unchanged, every loop
// segment an edge, no edge used more than twice, interior edges used once each way, boundary
// edges exactly the loop segments, triangle normals on the outward side of the surface.
FaceReport inspect_face(const AnalyticSurface& surface, const surface::FaceBoundary& boundary,
                        const surface::FaceMesh& mesh, const SizeField& size);

struct ClosedReport {
    index_t faces = 0;
    index_t open_edges = 0;          // used by one face
    index_t nonmanifold_edges = 0;   // used by more than two faces
    index_t misoriented_edges = 0;   // used twice in the same direction
    index_t nonmanifold_vertices = 0;
    index_t crossing_pairs = 0;      // interiors cross (exact)
    index_t touching_pairs = 0;      // faces with no common node that still touch (exact)
    long euler = 0;                  // V - E + F
    double volume = 0;               // enclosed, by the divergence theorem: > 0 when outward
};

// The boundary triangles and quads of the mesh as one surface.
ClosedReport inspect_closed(const HybridMesh& mesh);

}  // namespace tubemesh::testing
