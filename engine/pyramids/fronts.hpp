#pragma once
// What never changes about a front quad during the run: its corners, centroid M, normal n,
// size h, ideal apex N and the radii that bound what it may build and what it must look at.
// And the neighbour graph: which fronts can see each other's work.
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/point_index.hpp"
#include "engine/pyramids/build_pyramids.hpp"
#include "engine/pyramids/geometry.hpp"

namespace tubemesh::pyramids {

// Field order matters: a front scanning its neighbours reads their ideal apex and reach,
// then their nodes and corners, so those come first and share as few cache lines as they can.
struct alignas(64) Front {
    Vec3 ideal;  // N = M + shift + height·n
    // Every pyramid this front may build (base corners, any candidate or try node) lies in
    // the ball of this radius around N.
    double reach;
    std::array<index_t, 4> node;
    std::array<Vec3, 4> corner;
    Vec3 centroid;  // M
    Vec3 normal;    // n, unit, into the tet region
    // N over M: the paper's height_factor·h on the normal line, but for a front with an edge
    // on a boundary face whose wedge there is too narrow (wedge.hpp): at wedge_height_factor·h
    // (lower, with the default factors), and shifted in the quad's plane away from that edge;
    // and for a front facing another too closely, lower on the normal line (apart_factor).
    // Try node k is M + Rate·(N − M).
    Vec3 shift;
    double height;
    double h;       // mean edge length
    // Existing nodes within this distance of N are candidates.
    double candidate_radius;
    // Everything this front's criteria look at lies in the ball of this radius around N:
    // reach plus the largest distance threshold.
    double query_radius;
    // Candidates whose pyramid scores below this (scaled Jacobian) are refused:
    // min(min_quality, min_quality_ratio · the ideal pyramid's score), so a front whose
    // quad is too elongated for even its ideal pyramid to reach min_quality still gets one.
    double quality_floor;
    // The scaled Jacobian of the pyramid with apex N, the candidate most fronts take.
    double ideal_quality;
    // The second apex of a wedge front (PyramidOptions::wedge_wide_shift), tried in the normal
    // pass when N is refused; N itself when there is none.
    Vec3 wide;
    bool wedge = false;    // N was placed to open a wedge (wedge.hpp), not the paper's
    bool lowered = false;  // N was lowered for a facing front (PyramidOptions::apart_factor)
    // What the distance thresholds are relative to: h, or over a thin ring (front_scale) its
    // share of h, the gap ahead being that much thinner.
    double spacing = 0;
};

// The front has a second apex to try (Front::wide).
inline bool has_wide(const Front& f) {
    return f.wide.x != f.ideal.x || f.wide.y != f.ideal.y || f.wide.z != f.ideal.z;
}

// The fronts' ideal apexes in a point index (which reads coordinate arrays: hence the copy).
struct IdealApexes {
    std::vector<double> x, y, z;
    PointIndex index;
    explicit IdealApexes(std::span<const Front> fronts);
    static std::vector<double> coordinate(std::span<const Front> fronts, double Vec3::*c);
};

// Throws tubemesh::Error for a degenerate quad (zero area or zero edge length).
// boundary_triangles (3 ids each) tell which quad edges lie on a boundary face. With `apexes`,
// also the index of the fronts' ideal apexes (the one the lowering used when it lowered none).
// `room` (PyramidInput::front_scale): per quad, the share of the paper's apex height there is
// room for; empty or 1: all of it.
std::vector<Front> make_fronts(const HybridMesh& mesh, std::span<const index_t> quads,
                               std::span<const index_t> boundary_triangles, const PyramidOptions& opt,
                               std::unique_ptr<IdealApexes>* apexes = nullptr, std::span<const double> room = {});

// Compressed rows: row i is items[offset[i] .. offset[i+1]).
struct Adjacency {
    std::vector<std::size_t> offset;
    std::vector<index_t> items;
    std::span<const index_t> row(index_t i) const { return {items.data() + offset[i], offset[i + 1] - offset[i]}; }
};

// j is a neighbour of i when one's query ball meets the other's reach ball. A front's
// pyramid stays inside its reach ball and everything its criteria read lies in its query
// ball, so fronts that are not neighbours neither see nor touch each other's pyramids: they
// can be served concurrently, and the pyramids a front can see are those of its neighbours.
// Rows sorted by front index.
// `apexes`: the fronts' IdealApexes when at hand (built here otherwise).
Adjacency front_neighbours(std::span<const Front> fronts, const IdealApexes* apexes = nullptr);

}  // namespace tubemesh::pyramids
