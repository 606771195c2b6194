#pragma once
// Point location and Bowyer-Watson insertion in a UvMesh, under a local surface metric.
//
// The cavity is the set of triangles whose circumcircle, measured in the metric at the new
// point, holds the point; it never grows across a constrained edge. In-circle signs are plain
// floating point; what keeps the triangulation valid is the exact check that every rim edge
// sees the new point on its left (a star-shaped cavity), shrinking the cavity until it does.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/surface/uv_mesh.hpp"

namespace tubemesh::surface {

// J^T J from the derivatives (see Metric2).
Metric2 surface_metric(const SurfaceDerivatives& d);

// The upper-triangular factor U of M = U^T U, so |U du| is the metric length of du. Regularised
// where the metric degenerates (a pole, a cone's apex) so that it stays invertible.
struct MetricFactor {
    double u11, u12, u22;
    explicit MetricFactor(const Metric2& m);
    Uv apply(double du, double dv) const { return {u11 * du + u12 * dv, u22 * dv}; }
    Uv solve(double x, double y) const {  // U^-1 (x, y)
        const double dv = y / u22;
        return {(x - u12 * dv) / u11, dv};
    }
};

enum class WalkResult : std::uint8_t { Found, Blocked };

// Visibility walk from `start` to the triangle whose closure holds p. Blocked when the walk
// would cross a constrained edge or the hull: p is outside the region `start` is in, or hidden
// behind a boundary from it.
WalkResult locate(const UvMesh& mesh, index_t start, Uv p, index_t& found);

enum class InsertStatus : std::uint8_t {
    Inserted,
    Blocked,       // the walk met a boundary: the point is outside or behind one
    Duplicate,     // the point coincides with a vertex
    NotStarShaped, // no valid cavity holds it (it lies on a boundary edge)
    TooClose,      // nearer than the allowed spacing to a vertex of its cavity
};

class Inserter {
public:
    // Inserts v, walking from `start`. min_distance > 0 refuses points closer than that (in
    // space) to a vertex of their cavity. New triangles take the kInside flag of the triangle
    // the point lands in. On success created() lists them, and `vertex` is the new vertex.
    InsertStatus insert(UvMesh& mesh, index_t start, const VertexData& v, double min_distance, index_t& vertex);

    // The triangle holding a point that coincided with a vertex (status Duplicate).
    index_t duplicate_of() const { return duplicate_; }
    std::span<const index_t> created() const { return created_; }

private:
    struct RimEdge {
        index_t a, b;      // counter-clockwise around the cavity
        index_t outer;     // packed neighbour across it (3n + j) or kNoIndex
        index_t owner;     // cavity triangle it belongs to
        bool constrained;
    };
    bool build_cavity(UvMesh& mesh, index_t t0, Uv p, const MetricFactor& f);

    std::vector<index_t> cavity_, banned_, created_;
    std::vector<index_t> fan_slot_;  // per vertex: new triangle whose rim edge starts there
    std::vector<RimEdge> rim_;
    index_t duplicate_ = kNoIndex;
};

}  // namespace tubemesh::surface
