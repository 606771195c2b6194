#pragma once
// The tet step's working mesh (paper §5): the tetrahedra that fill the region bounded by the
// closed front (surface triangles + the pyramids' free triangles), handed from boundary
// recovery to interior-point refinement to optimisation.
//
//   xyz              3 coordinates per point. Points [0, front_points) are the front's nodes,
//                    in the caller's order; they never move and are never removed. Points
//                    after them are Steiner points of the recovery and interior points.
//   tets             the kernel's store (engine/delaunay/tet_store.hpp): 4 point ids per tet,
//                    positively oriented (orient3d(v0, v1, v2, v3) > 0); neighbour 4*t + f
//                    across face f (opposite vertex f). A face with kNoAdjacent is a front
//                    triangle: the region's boundary is exactly the front, so cavities and
//                    flips stop there by construction. Free slots (vertex[0] == kFreeSlot)
//                    may exist while a phase runs; every phase leaves none behind.
//   front            3 point ids per front triangle, normal pointing out of the region
//                    (the order of PipelineResult::tet_front).
//
// Every phase keeps the invariants above, so any phase can be tested on its own on a domain
// built by delaunay() of points in a box (the hull faces are then the front).
#include <array>
#include <cstddef>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/delaunay/tet_store.hpp"
#include "engine/core/vec3.hpp"

namespace tubemesh::tets {

struct TetDomain {
    std::vector<double> xyz;
    index_t front_points = 0;
    delaunay::TetStore tets;
    std::vector<index_t> front;
    // Front points the optimisation's smoothing may move as well (tet_step.hpp, move_apexes):
    // pyramid apexes that no hex, boundary face or pyramid base holds. apex_rank[p] (p below
    // front_points) is kNoIndex for a point that stays, else k: its pyramids' base quads (4
    // point ids each, the mesh's order) are apex_bases[apex_at[k] .. apex_at[k + 1]), and a move
    // keeps each of them at a scaled Jacobian of at least apex_floor. Empty: no front point moves.
    std::vector<index_t> apex_rank, apex_at;
    std::vector<std::array<index_t, 4>> apex_bases;
    double apex_floor = 0.5;
    // Front points that may slide in the plane of their flat face (tet_step.hpp, slide_surface):
    // slide_rank[p] (p below front_points) is kNoIndex for a point that stays, else k: its moves
    // keep it in the plane dot(n, x) = slide_offset[k] with unit normal n = slide_normal[k].
    // Empty: none slides.
    std::vector<index_t> slide_rank;
    std::vector<Vec3> slide_normal;
    std::vector<double> slide_offset;

    bool is_apex(index_t p) const { return p < front_points && !apex_rank.empty() && apex_rank[p] != kNoIndex; }
    bool slides(index_t p) const { return p < front_points && !slide_rank.empty() && slide_rank[p] != kNoIndex; }
    // True for a point the smoothing may move.
    bool movable(index_t p) const { return p >= front_points || is_apex(p) || slides(p); }
    // True when some front point may move.
    bool front_moves() const { return !apex_rank.empty() || !slide_rank.empty(); }

    index_t point_count() const { return static_cast<index_t>(xyz.size() / 3); }
    const double* point(index_t p) const { return xyz.data() + std::size_t{3} * p; }
};

// The tets boundary recovery left, kept for the relaxation to insert points into again: over
// the domain's first `points` points, which nothing later moves or renumbers, so only the tets
// are copied (TetStore has no copy constructor: a large copy is always asked for by name).
struct RecoveredTets {
    delaunay::TetStore tets;
    index_t points = 0;
    // Points [points, points + in_place) of the domain, set by the refinement: the far field it
    // inserted first, which the relaxation keeps where it is and inserts again before the others.
    index_t in_place = 0;
};
RecoveredTets recovered_tets(const TetDomain& d);

// Removes the points from `first` on that no tet uses (the ones a kernel run skipped) and moves
// the later ones down, in order; points before `first` keep their ids. Returns the old -> new
// id map (kNoIndex for a removed point).
std::vector<index_t> drop_unused_points(TetDomain& d, index_t first);

}  // namespace tubemesh::tets
