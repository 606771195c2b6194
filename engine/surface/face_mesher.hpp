#pragma once
// Triangles on one trimmed B-rep face, conforming to the nodes already placed on its boundary.
//
// The face is meshed in its parameter plane by frontal Delaunay refinement (Rebay 1993, as in
// Gmsh's "frontal-Delaunay"): a constrained Delaunay triangulation of the boundary nodes is
// refined by inserting, for the largest unfinished triangle next to the finished region, the
// point that makes an ideal triangle on their shared edge. Lengths and circles are measured in
// the surface's first fundamental form J^T J, so triangles that are round in space come out
// round whatever the parametrisation stretches; the target size comes from a SizeField in
// space. Edge flips, smoothing and collapses, judged by angles in space, finish the mesh
// (surface_optimisation.hpp).
//
// A pole or a cone's apex is a degenerate boundary edge: several loop occurrences of one node
// at different uv. Triangles between two of them collapse to nothing in space and are left
// out of the result; the others make a closed fan around the node.
//
// Boundary nodes are never moved and boundary segments are never split: the caller places
// them once (shared B-rep edges, rings' outer polygons) so neighbouring faces meet node for
// node. A periodic face is cut along its seam: the seam's nodes appear twice in the loops, at
// uv one period apart, and both occurrences become the same output node.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/geometry/surface_map.hpp"
#include "engine/sizing/field/size_field.hpp"

namespace tubemesh::surface {

class FaceMesherState;

// The fixed boundary of one face.
struct FaceBoundary {
    // Distinct boundary nodes: the caller's id (a HybridMesh point id in the pipeline) and the
    // exact position, which the output keeps.
    std::vector<index_t> node_id;
    std::vector<Vec3> xyz;
    // Loops, outer first, then holes, each a closed polyline of node occurrences (first not
    // repeated): loop k is entries [loop_begin[k], loop_begin[k+1]) of loop_node / loop_uv.
    // Either orientation is accepted. A node may occur more than once when its uv differs
    // (the two sides of a seam).
    std::vector<index_t> loop_begin{0};
    std::vector<index_t> loop_node;  // index into node_id
    std::vector<Uv> loop_uv;

    index_t add_node(index_t id, const Vec3& p);
    void add_loop_point(index_t node, Uv uv);  // appends to the loop being built
    void close_loop();                         // ends the loop being built
    index_t loop_count() const { return static_cast<index_t>(loop_begin.size() - 1); }
    index_t node_count() const { return static_cast<index_t>(node_id.size()); }
};

struct FaceMeshOptions {
    // Frontal refinement leaves a triangle alone once its circumradius is at most this factor
    // times that of the equilateral triangle of the local target size. Smaller: more and
    // rounder triangles, slower. Of 1.2, 1.3 and 1.4, 1.3 met the angle bounds on every test
    // face with the fewest triangles.
    double accept_ratio = 1.3;
    // A new point closer than this fraction of its target size to a vertex of its cavity is
    // not inserted (fronts met there; the optimisation tidies up). Larger values keep the
    // small triangles of colliding fronts out, which is what keeps neighbour sizes within
    // 1.5; 0.6 was the best of 0.3 to 0.6 on the test faces.
    double min_spacing = 0.6;
    // Rounds of (smoothing sweep + flip sweep + collapse sweep) after refinement, then at most
    // as many grading sweeps; each stops early when it changes nothing.
    int optimisation_passes = 3;
};

struct FaceMeshStats {
    index_t points_inserted = 0;
    index_t points_refused = 0;  // candidates not inserted (outside, too close, no valid cavity)
    index_t flips = 0;
    index_t moves = 0;      // accepted smoothing and grading moves
    index_t collapses = 0;  // interior vertices removed by the optimisation
};

// One face's triangles. Nodes [0, boundary_count) are the FaceBoundary's nodes in its order;
// the rest are new interior nodes, in creation order.
struct FaceMesh {
    index_t boundary_count = 0;
    std::vector<Vec3> xyz;
    std::vector<Uv> interior_uv;    // uv of node boundary_count + k
    std::vector<index_t> triangles; // 3 per triangle; right-hand normal = the solid's outward normal
    FaceMeshStats stats;

    index_t triangle_count() const { return static_cast<index_t>(triangles.size() / 3); }
};

// Meshes faces one after another, keeping its scratch memory between them: one per thread.
// The result depends only on the input, never on what the mesher meshed before.
class FaceMesher {
public:
    FaceMesher();
    ~FaceMesher();
    FaceMesher(FaceMesher&&) noexcept;
    FaceMesher& operator=(FaceMesher&&) noexcept;

    // Throws tubemesh::Error (naming the face) for a boundary that cannot be respected:
    // loops that cross or touch themselves, two nodes at one uv, fewer than 3 loop points.
    void mesh(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
              const FaceMeshOptions& options, FaceMesh& out);

private:
    std::unique_ptr<FaceMesherState> state_;
};

// One face with a fresh mesher.
FaceMesh mesh_face(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
                   const FaceMeshOptions& options = {});

}  // namespace tubemesh::surface
