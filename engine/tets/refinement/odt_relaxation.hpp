#pragma once
// Optimal-Delaunay relaxation of the interior points, between refinement and optimisation.
//
// Refinement puts each interior point where one front face asked for it and keeps it unless it
// lies too close to another, so neighbouring points sit at uneven distances and the Delaunay
// tets between them are uneven too; the optimisation's moves must each raise their own star's
// quality, and stop in the first local optimum. One relaxation iteration instead moves every
// free point to its star's size-weighted ODT position (the mean of the star's circumcentres,
// each tet weighted by its volume / h^3, h the mean target size at its corners: Chen and Holst's
// optimal Delaunay triangulation with the point density of the size field, as in Alliez et al.
// 2005), kept only as far as no tet of its star inverts (its neighbours where they were). After
// the last iteration all free points are inserted again into the recovered front mesh: the tets
// become the constrained Delaunay tets of the moved points (figures at
// RelaxationOptions::iterations). Earlier iterations move on the stars as they are.
//
// Parallel and deterministic: every point's move is computed from the positions before the
// round, and the insertion runs the Delaunay kernel with a fixed part count.
// Points [0, recovered.points) (the front's and recovery's Steiner points) never move, nor do the
// far field's [recovered.points, recovered.points + recovered.in_place), which the reinsertion puts
// in first.
#include <cstdint>
#include <span>

#include "engine/core/parallelism.hpp"
#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct RelaxationOptions {
    // Move rounds before the reinsertion (one, unless reinsert_each_iteration); 0 = none.
    // Default 1: with the far field inserted first and kept in place, a second round raised the
    // mean collapse little for more time (bench/results/tuning-notes.md).
    int iterations = 1;
    // Insert the points again after every iteration instead of after the last one only. Off by
    // default: each insertion rebuilds all the interior tets, the largest cost of the relaxation,
    // while moving twice on the first stars loses little (bench/results/tuning-notes.md).
    bool reinsert_each_iteration = false;
};

struct RelaxationStats {
    int iterations = 0;
    std::uint64_t moves = 0;   // point moves over all iterations
    int reinsertions = 0;      // times the free points were inserted again
    index_t second_walks = 0;  // reinsertions whose first walk ran into the front
    index_t dropped = 0;       // points the kernel could not insert again (removed, ids compacted)
    double seconds = 0;
};

// `recovered`: the tets boundary recovery left (before refinement), over the first points of
// `domain`, filling the same region. `sizes`: the target size at each
// point of `domain` by id (point_sizes), read as the density's h; a point keeps its size when
// it moves (within its star, so by about its h at most, and the field grows by at most g - 1
// per unit length).
// `domain` keeps its invariants (tet_domain.hpp); the points the kernel skips on reinsertion
// (none on the reference meshes or the test cube) are removed and the later ids moved
// down, in order.
// The kernel inserts with par.parts parts, in the caller's oneTBB arena: the result depends on
// the input and that count only.
RelaxationStats relax_points(TetDomain& domain, const RecoveredTets& recovered, std::span<const double> sizes,
                             const Parallelism& par, const RelaxationOptions& options = {}, const Pulse& pulse = {});
// The same, spending `recovered`: its tets become the last insertion's start instead of a copy
// of them (the copy and the original together were the relaxation's memory peak).
RelaxationStats relax_points(TetDomain& domain, RecoveredTets&& recovered, std::span<const double> sizes,
                             const Parallelism& par, const RelaxationOptions& options = {}, const Pulse& pulse = {});

}  // namespace tubemesh::tets
