#pragma once
// Delaunay tetrahedralisation of a point set: one call, an options struct, a result with
// statistics. The kernel (ghost tets, exact predicates with symbolic tie-breaks, parallel
// passes over spatial parts) is described in triangulation.hpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/parallelism.hpp"
#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/delaunay/tet_store.hpp"

namespace tubemesh::delaunay {

struct DelaunayOptions {
    // Passes with fewer points than this per part run serially (a pass has a fixed cost:
    // quantiles, start tets, postponed points near the cuts).
    index_t min_points_per_part = 1024;
    // Enclose the points in an axis-aligned box, grown by `box_margin` times the bounding
    // box diagonal on every side, whose 8 corners are inserted first: the paper's start for
    // boundary recovery (its "box split into five tets"; here the corners, all on one sphere,
    // are split by the tie-break). The corners get ids n..n+7 (corner k has x = hi if k & 1,
    // y = hi if k & 2, z = hi if k & 4); the hull is then the box.
    bool bounding_box = false;
    double box_margin = 0.1;
    // The caller's sign of life during the insertion (engine/core/pulse.hpp); may throw.
    Pulse pulse;
};

struct DelaunayStats {
    index_t points = 0;  // input points (without box corners)
    index_t tets = 0;
    index_t duplicates = 0;
    unsigned threads = 0;
    unsigned partitions = 0;
    std::uint64_t passes = 0;             // parallel passes
    std::uint64_t conflicts = 0;          // insertions postponed: another part's tets needed
    std::uint64_t walk_conflicts = 0;     // of which found by the walk
    std::uint64_t postponed_no_room = 0;  // insertions postponed: the part's slot quota ran out
    std::uint64_t serial_insertions = 0;  // points inserted outside parallel passes
    std::uint64_t walk_steps = 0;
    std::size_t peak_bytes = 0;  // tet store and point arrays at their largest
    double bytes_per_tet = 0;    // peak_bytes / tets
    double seconds_order = 0;    // BRIO rounds and Hilbert sort
    double seconds_insert = 0;
    double seconds_passes = 0;  // of seconds_insert: parallel passes
    double seconds_serial = 0;  // of seconds_insert: serial insertion (small rounds, stragglers)
    double seconds_finish = 0;  // ghost removal, compaction, global ids
    double seconds_total = 0;
};

struct DelaunayResult {
    // Tets only, no ghosts or holes. vertices(): 4 point ids per tet, positively oriented
    // (orient3d(v0, v1, v2, v3) > 0). neighbours(): 4*tet + face for the tet across face i
    // (opposite vertex i), kNoAdjacent on the convex hull.
    TetStore tets;
    // Points not inserted because an earlier point has the same coordinates:
    // {point id, id of the point kept}, sorted.
    std::vector<std::pair<index_t, index_t>> duplicates;
    // With DelaunayOptions::bounding_box: the corner coordinates (ids n..n+7).
    std::vector<std::array<double, 3>> box_corners;
    DelaunayStats stats;

    index_t tet_count() const { return tets.size(); }
};

// Throws tubemesh::Error when the coordinate arrays differ in length or hold a NaN or an
// infinity. Fewer than four affinely independent points give no tets (and no error).
// Runs in the caller's oneTBB arena (limit_threads sets its size), with par.parts spatial parts
// per parallel pass: the same input and part count give the same tets in the same order,
// whatever the thread count and timing (parts never race, so determinism costs nothing).
DelaunayResult delaunay(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                        const Parallelism& par, const DelaunayOptions& options = {});

}  // namespace tubemesh::delaunay
