#pragma once
// The incremental Delaunay kernel: Bowyer-Watson cavity insertion with a visibility walk,
// ghost tets for the convex hull, and parallel rounds over spatial parts.
//
// Ghost tets. The hull is closed by "ghost" tets that join each hull triangle to one vertex
// at infinity (kInfiniteVertex). A ghost is in conflict with a point that sees its hull
// triangle from outside, or that lies in the triangle's plane inside its circumcircle. With
// ghosts the kernel computes exactly the Delaunay tetrahedralisation of the points (their
// convex hull), with no bounding vertices to remove and no "far enough" to guess. For the
// paper's "box split into tets" start, insert the 8 box corners as the first points.
//
// Degeneracies. Orientations are exact (never perturbed), so every tet has a strictly
// positive volume. Insphere ties (co-spherical points) are broken by symbolic perturbation
// ordered by the points' global ids, the same tie-break every other module uses.
//
// Parallel passes. A batch of points is split into `parts`; each part is inserted by one
// task, which may change only tets whose finite vertices all belong to its part (owner_).
// The first pass cuts the Hilbert curve into ranges of equal point counts, so every part
// inserts one stretch of the curve; later passes cut slabs across the layer of points left
// along the previous borders. A walk or cavity that needs another part's tet is not locked:
// the point is postponed to the next pass (a counted conflict), and the last stragglers are
// inserted serially. Tet slots come from per-part quotas fixed before the pass, and a walk
// only crosses tets no other part can change, so a part's work depends on the state before
// the pass and its own points, never on timing: the result is a pure function of the input
// and the part count, whatever the thread count.
//
// Usage: add_points(), start(), insert() as often as wanted (every insert keeps the
// triangulation Delaunay), finish() once to get the tets.
//
// Constrained mode (the tet step's refinement, paper §5): adopt() takes over a finished mesh
// whose kNoAdjacent faces are a boundary (the front), with no ghosts. insert() then grows each
// cavity only across faces that have a tet behind them, so a front face is never removed: it
// becomes a face of a new tet. The mesh need not be Delaunay (after boundary recovery it is
// not), so a cavity may not be star-shaped from its point; it is shrunk, tet by tet, until
// every boundary face is seen from the point (every new tet has a positive volume), and the
// point is skipped (InsertStatus::Blocked, listed in blocked()) when the tet holding it would
// have to go, or when it lies outside the region. Parts, passes and determinism are as above.
// The unconstrained path is a separate template instance and pays nothing for this.
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/delaunay/tet_store.hpp"

namespace tubemesh::delaunay {

// What happened to one point; the expected outcomes of the hot loop, not errors.
enum class InsertStatus : std::uint8_t {
    Inserted,
    Duplicate,  // same coordinates as a vertex already in the triangulation: not inserted
    Conflict,   // walk or cavity needs another part's tets: retry in a later pass
    NoRoom,     // the part's slot quota is used up: retry in a later pass
    Blocked,    // constrained mode: outside the region, on a front face, or its tet would go
};

struct KernelCounters {
    std::uint64_t inserted = 0;
    std::uint64_t conflicts = 0;       // postponed insertions: another part's tets needed
    std::uint64_t walk_conflicts = 0;  // of which by the walk
    std::uint64_t no_room = 0;         // postponed insertions: quota used up
    std::uint64_t walk_steps = 0;
    std::uint64_t tets_created = 0;
    std::uint64_t passes = 0;  // parallel passes
    std::uint64_t serial_inserted = 0;
    std::uint64_t blocked = 0;   // constrained mode: points skipped (InsertStatus::Blocked)
    std::uint64_t shrunk = 0;    // constrained mode: cavities shrunk to be star-shaped
    // Conflict tests the insphere filter left undecided (exact ties, as co-spherical points of
    // structured layers give, and near-ties), and of those the ones a cavity met again and
    // answered from its earlier exact result.
    std::uint64_t exact_insphere = 0;
    std::uint64_t exact_insphere_reused = 0;
    double seconds_passes = 0;  // wall time in parallel passes, set-up included
    double seconds_serial = 0;  // wall time of serial insertion

    KernelCounters& operator+=(const KernelCounters& o);
};

class Triangulation {
public:
    Triangulation();
    ~Triangulation();
    Triangulation(const Triangulation&) = delete;
    Triangulation& operator=(const Triangulation&) = delete;

    // Appends points; `global_ids` order the symbolic perturbation and name the vertices in
    // finish()'s output. Returns the kernel id of the first one (kernel ids are consecutive;
    // nearby ids should be nearby points, e.g. in Hilbert order, for cache locality).
    index_t add_points(std::span<const double> xyz, std::span<const index_t> global_ids);
    // The same for points (x[i], y[i], z[i]) with global id i, for i in `ids` (in that order).
    index_t add_points(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                       std::span<const index_t> ids);
    index_t point_count() const { return static_cast<index_t>(global_.size()); }
    const double* point(index_t v) const { return xyz_.data() + std::size_t{3} * v; }
    // All points, 3 coordinates each, by kernel id (valid until points are added).
    std::span<const double> points() const { return xyz_; }
    index_t global_id(index_t v) const { return global_[v]; }

    void reserve_points(std::size_t n);
    // Hilbert keys of all points added so far, in kernel id order. With keys, the first pass
    // of every insert() splits the points (which must then follow the curve) into curve
    // ranges, so each part walks along one stretch of the curve; without, into slabs.
    void set_curve_keys(std::vector<std::uint64_t> keys);
    void reserve_tets(std::size_t n) { tets_.reserve(n); }
    // Called every kPulseEvery insertions of a part or of the serial stragglers, from the
    // thread inserting them; it may throw to stop the run (the other parts then stop at their
    // next pulse).
    void set_pulse(Pulse pulse) { pulse_ = std::move(pulse); }
    static constexpr std::size_t kPulseEvery = 1024;

    // Constrained mode: takes over the points (kernel id = global id = position in `xyz`) and
    // the tets of a finished mesh (positive tets, no free slots, kNoAdjacent on the boundary).
    // Instead of start(); points added later get the ids the caller gives them.
    void adopt(std::vector<double>&& xyz, TetStore&& tets);
    void adopt(std::span<const double> xyz, TetStore&& tets) { adopt(std::vector<double>(xyz.begin(), xyz.end()), std::move(tets)); }
    bool constrained() const { return constrained_; }
    // Constrained mode: a live tet near point v, where a serial walk to v starts again when the
    // walk from the previous insertion runs into the front (non-convex regions).
    void set_walk_start(index_t v, index_t tet) { seed_[v] = tet; }
    // Constrained mode: kernel ids of the points skipped (InsertStatus::Blocked), in the order
    // met (deterministic for a given part count).
    const std::vector<index_t>& blocked() const { return blocked_; }

    // Makes the first tet from four affinely independent points among `candidates` (which
    // should be spread out, e.g. the first BRIO round). Returns the 4 kernel ids used, in
    // no particular order, or an empty vector when all candidates are coplanar.
    std::vector<index_t> start(std::span<const index_t> candidates);
    bool started() const { return tets_.size() > 0; }

    // Inserts the points (kernel ids, in insertion order) with `parts` spatial parts per
    // parallel pass; passes with fewer than `min_points_per_part` points per part, and the
    // last stragglers, are inserted serially. Runs in the caller's oneTBB arena. Duplicates are appended to duplicates() as {kernel id, kernel id kept}.
    void insert(std::span<const index_t> points, unsigned parts, index_t min_points_per_part);

    // Removes ghost and free slots (hull faces get kNoAdjacent), maps vertices and
    // duplicates() to global ids and hands over the store. No insert() afterwards.
    TetStore finish();
    // Hands over the points (by kernel id), after finish(): the tet step keeps one point array
    // that goes from phase to phase instead of copies.
    std::vector<double> take_points() { return std::move(xyz_); }

    // The live store: ghost tets (one vertex kInfiniteVertex) and free slots (vertex[0] ==
    // kFreeSlot) included.
    const TetStore& store() const { return tets_; }
    // Tets in the store less its free slots (ghosts included, which constrained mode has none of).
    index_t live_tets() const { return tets_.size() - static_cast<index_t>(free_.size()); }
    const std::vector<std::pair<index_t, index_t>>& duplicates() const { return duplicates_; }
    const KernelCounters& counters() const { return counters_; }
    // Largest number of bytes held by the tet store and point arrays so far.
    std::size_t peak_bytes() const { return peak_bytes_; }

    struct Part;     // one part of a pass: its region, slot quota, walk hint, outcome
    struct Scratch;  // per-thread cavity buffers

private:
    // kFront: constrained mode (cavities stop at kNoAdjacent faces and are made star-shaped).
    template <bool kParts, bool kFront>
    InsertStatus insert_one(index_t p, Part& part, Scratch& s);
    template <bool kParts, bool kFront>
    InsertStatus locate(index_t p, Part& part, index_t& tet, index_t& vertex);
    // Constrained mode: shrinks the cavity in `s` until p sees every boundary face; false when
    // the tet `start` (holding p) would have to go.
    bool shrink_to_visible(index_t p, index_t start, Scratch& s);
    bool in_conflict(index_t tet, const double* pp, index_t p, Part& part, Scratch& s) const;
    bool tie_in_conflict(index_t tet, const double* pp, index_t p, Part& part, Scratch& s) const;
    bool ghost_in_conflict(index_t tet, const double* pp, index_t p) const;
    int insphere_exact(const index_t* v, const double* pp, index_t p) const;  // with ties broken
    void link_new_tets(Scratch& s);
    bool take_slots(Part& part, std::size_t n, std::vector<index_t>& out);

    void insert_serial(std::span<const index_t> points);
    // axis < 0: split by curve keys, else into slabs along that axis.
    std::vector<index_t> insert_pass(std::span<const index_t> points, unsigned parts, int axis);
    index_t find_start(Part& part, index_t first_point, Scratch& s);
    void note_memory();
    void advise_point_arrays();

    std::vector<double> xyz_;
    std::vector<index_t> global_;
    // Per-vertex scratch of the cavity linking, kNoIndex between insertions. A cavity's
    // vertices all belong to its part, so parts never touch the same entries.
    std::vector<index_t> local_;
    std::vector<std::uint64_t> key_;   // Hilbert key per vertex (set_curve_keys), for partitions
    std::vector<std::uint8_t> owner_;  // the part owning each vertex in the current pass
    TetStore tets_;
    std::vector<index_t> free_;  // free slots, reused first
    index_t hint_ = kNoIndex;    // a live finite tet near the last insertion
    double growth_ = 7.0;        // new slots per inserted point, for part quotas
    std::vector<std::pair<index_t, index_t>> duplicates_;
    bool constrained_ = false;
    std::vector<index_t> seed_;     // constrained mode: set_walk_start() per vertex, or kNoIndex
    std::vector<index_t> blocked_;  // constrained mode: skipped points
    KernelCounters counters_;
    Pulse pulse_;
    std::size_t peak_bytes_ = 0;
    struct ScratchPool;
    std::unique_ptr<ScratchPool> scratch_;
};

}  // namespace tubemesh::delaunay
