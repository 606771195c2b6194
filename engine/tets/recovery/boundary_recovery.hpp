#pragma once
// Boundary tetrahedralisation and boundary recovery (paper §5, second paragraph): the first
// tets of the tet step, filling exactly the region bounded by the closed front.
//
//  1. Delaunay tetrahedralisation of the front points inside a bounding box (the paper's box
//     split into tets; engine/delaunay).
//  2. Every front edge, then every front triangle, made a tet edge / face: flips first (2-3,
//     and edge removal: 3-2, 4-4, n -> 2n-4), each required not to add an element crossing
//     the missing one, so every flip makes progress; where no flip helps, the shell of an edge
//     whose ring holds both ends of a missing front edge rebuilt around it (with a new point
//     on either side where needed: a flat front face's other diagonal), else a Steiner point
//     on an interior edge or inside a pair of tets (never on the front). The front itself is
//     never changed. Steiner points are removed again by contraction where that leaves
//     positive tets.
//  3. The tets on the outer side of the front (outside the solid, inside rings and pyramids)
//     are removed by a flood fill across non-front faces, seeded on both sides of every front
//     triangle; the box corners go with them.
#include <cstdint>
#include <span>

#include "engine/core/parallelism.hpp"
#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct RecoveryOptions {
    // Box around the points, grown by this fraction of their bounding box diagonal per side.
    double box_margin = 0.1;
    // Largest ring (tets around an edge) an edge-removal flip tries (O(n^3) per try), 3 to
    // kMaxRecoveryRing (recovery_flips.hpp).
    int max_ring = 16;
    // Steiner points one missing edge or triangle may need before recovery gives up (an error).
    int max_steiner_per_element = 64;
    // Flips plus Steiner points one missing element may take before recovery gives up.
    int max_steps_per_element = 4096;
    // Try to remove the Steiner points once the front is recovered.
    bool remove_steiner = true;
};

struct RecoveryStats {
    index_t front_points = 0;     // input points (used by the front)
    index_t front_triangles = 0;
    index_t front_edges = 0;
    index_t unused_points = 0;    // input points no front triangle names (not tetrahedralised)
    index_t delaunay_tets = 0;    // with the box
    index_t missing_edges = 0;    // front edges not in the Delaunay tetrahedralisation
    index_t missing_faces = 0;    // front triangles not faces after edge recovery
    index_t edges_by_flips = 0;   // missing edges recovered without a Steiner point
    index_t faces_by_flips = 0;   // missing triangles recovered without a Steiner point
    std::uint64_t flips23 = 0;
    std::uint64_t edge_removals = 0;  // of which 3-2 and 4-4 below
    std::uint64_t flips32 = 0;
    std::uint64_t flips44 = 0;
    index_t steiner_inserted = 0;
    index_t steiner_removed = 0;
    index_t steiner_kept = 0;     // Steiner points in the result's tets
    index_t tets = 0;             // in the result
    double seconds_delaunay = 0;
    double seconds_edges = 0;
    double seconds_faces = 0;
    double seconds_steiner_removal = 0;
    double seconds_classify = 0;
    double seconds_total = 0;
};

// What recover_boundary throws when flips and Steiner points give up on a missing front element
// (the front passed its checks): other sizes of the front may recover, so the pipeline says so.
class RecoveryGaveUp : public Error {
public:
    using Error::Error;
};

// xyz: 3 coordinates per point; front: 3 point ids per triangle, normal out of the region.
// Points no front triangle names stay in the domain's xyz (ids are kept) but in no tet.
// Throws tubemesh::Error for an open, non-manifold or inconsistently oriented front, for points
// with equal coordinates, for a self-intersecting front (front elements crossing, a front
// point on a front edge or triangle), for a front oriented inwards, and RecoveryGaveUp when
// recovery fails.
// The Delaunay kernel runs with par.parts parts (the result depends on the input and that count
// only); it and recovery's parallel loops (front checks, which front elements are present, the
// tets beside the front) run in the caller's oneTBB arena; the flips and Steiner points are serial.
// `pulse` is called during the Delaunay insertion and between batches of recovered elements
// (engine/core/pulse.hpp); what it throws leaves recovery.
TetDomain recover_boundary(std::span<const double> xyz, std::span<const index_t> front, const Parallelism& par,
                           const RecoveryOptions& options = {}, RecoveryStats* stats = nullptr,
                           const Pulse& pulse = {});

}  // namespace tubemesh::tets
