#pragma once
// Advancing-front interior points (paper §5): ideal points proposed on the active front and
// filtered by the size field. Functions of the mesh state (select_points also brings a
// GrowingPoints' trees up to date, so one object serves one caller at a time): refine.cpp
// inserts the result.
// The memo overloads carry what an unchanged tet or face would recompute from one round to the
// next; they return exactly what the plain ones do (tests/tets_refine_test.cpp checks this).
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/delaunay/tet_store.hpp"

namespace tubemesh::tets {

class ControlSpace;

// A proposed point: where, the size there, and the tet of the mesh that holds it.
struct Candidate {
    double p[3];
    double h;
    index_t tet;
    index_t source;  // the front node whose graded term gives h (kNoIndex for a lattice node)
};

// Points given by kernel-style arrays: 3 coordinates per point id, and the target size h at
// each point (point_sizes for the points there before refinement, a candidate's own h for a
// point it inserts): a point's h is asked of the control space once, then read wherever a tet
// or a face needs the size at its corners.
struct MeshView {
    const delaunay::TetStore& tets;  // may hold free slots (vertex[0] == kFreeSlot)
    std::span<const double> xyz;
    std::span<const double> h;  // one per point id
    // Per point id, the front node whose graded term gives its h (ControlSpace::source, a
    // candidate's source for a point it inserts; kNoIndex: none, h is the far size). Needed by
    // propose_points.
    std::span<const index_t> source = {};
};

// The control space's h at each point (3 coordinates each), in parallel.
std::vector<double> point_sizes(std::span<const double> xyz, const ControlSpace& space);
// ControlSpace::source at each point, in parallel.
std::vector<index_t> point_sources(std::span<const double> xyz, const ControlSpace& space);

// True when the tet's mean edge length exceeds `tolerance` times the mean h of its four points:
// as good as h at the centroid, without a nearest-node query per new tet.
bool tet_too_big(const MeshView& mesh, index_t tet, double tolerance);

// The active front: faces 4*t+f of too-big tets t whose other side is the front or a tet that
// is not too big (the front of the resolved region), in increasing order. Parallel.
std::vector<index_t> active_faces(const MeshView& mesh, double tolerance);

// tet_too_big's answers kept from one round to the next, per tet slot: points never move during
// refinement and their sizes are fixed, so a slot holding the tet it held at the last call has
// the same answer, and a round only tests the tets the kernel made. Every tet the kernel makes
// has the point it inserts as a vertex, so a slot's tet is new exactly when it names a point
// added since the last call: no copy of the vertex rows is kept. Valid for one kernel mesh, one
// point array and size array (appended to only) and one tolerance.
struct TooBigMemo {
    std::vector<std::uint8_t> big;  // the answer for slot t at the last call (0 for a free slot)
    index_t points = 0;             // points at the last call: a tet naming a later one is new
    std::uint64_t tests = 0;        // tet_too_big calls made through the memo
};

// active_faces with the answers of earlier rounds reused (and this round's stored) in `memo`;
// the same faces as without it.
std::vector<index_t> active_faces(const MeshView& mesh, double tolerance, TooBigMemo& memo);

// The far-field lattice: where the size field is the far size S and the front is far away, an
// ideal point is replaced by the nearest node of a body-centred cubic lattice (cube corners and
// centres, a corner at the origin), moved by at most 1e-4 of the cube edge per axis (a hash of
// the node: no exact co-spherical ties for the kernel). Advancing-front points there sit at
// random offsets from one another, and flips and smoothing only partly repair that; the
// lattice's Delaunay tets are all alike, with collapse 0.958. The front-near and graded parts
// stay advancing front.
struct FarLattice {
    double spacing = 0;    // cube edge over S; 0: no lattice
    double clearance = 0;  // least distance from a lattice point to the nearest front node, over S
};

// The far-field lattice's nodes in the box [lo, hi] where the lattice replaces ideal points (h
// is S and no front node lies within the clearance: ControlSpace::far_and_clear), each with
// its offset: the very points propose_points snaps to there. Nodes in a fixed order (x
// fastest, corners before centres), 3 coordinates each; empty without the lattice, and when the
// box holds more than `max_nodes` nodes (each is tested against the front). Parallel.
std::vector<double> far_lattice_points(const double* lo, const double* hi, const ControlSpace& space,
                                       const FarLattice& lattice, double max_nodes);

// The target size at p carried by the mesh points v[0..4) (a tet's corners near p): the control
// space's graded minimum min(S, s_i + (g - 1) |p - x_i|) taken over the front nodes i that
// decide h at those points (MeshView::source) instead of over p's nearest front nodes, so no
// nearest-node query per point. Seeded from the front (point_sources) and passed on to each
// inserted point, the sources follow the front outwards; since the distance is measured to
// the node itself, not summed along a chain of points, h grows as the control space's does.
struct CarriedSize {
    double h;
    index_t source;  // kNoIndex when h is the far size
};
CarriedSize carried_size(const MeshView& mesh, const index_t* v, const double* p, const ControlSpace& space);

// One ideal point per active face: the apex of a near-regular tet of size h on the face, on
// the side of the face's tet, h carried by that tet's corners (carried_size) halfway to the
// apex that the mean h of the face's points gives; dropped when a walk from that tet leaves
// the region through the front. The candidate's h is carried by the corners of the tet that
// holds it (the far size for a lattice node). `space` gives S, the gradation and, for the
// lattice, the clearance test. Parallel; the order follows `faces`.
std::vector<Candidate> propose_points(const MeshView& mesh, std::span<const index_t> faces,
                                      const ControlSpace& space, const FarLattice& lattice = {});

// Ideal points of the previous round's active faces, by face code 4*t+f with t's point ids in
// order: the ideal point depends only on those, so a face that is active again in an unchanged
// tet reuses it (its walk to the holding tet and its h there, which depend on the mesh, are redone).
// Valid for one point array and size array (appended to only), one ControlSpace and one FarLattice.
struct ProposalMemo {
    struct Entry {
        index_t face;
        std::array<index_t, 4> ids;
        double p[3];
        double h;  // the far size for a lattice node, else NaN (carried by the holding tet)
    };
    std::vector<Entry> entries;  // increasing face
    std::atomic<std::uint64_t> reused_total{0};  // faces that reused an entry
};

// propose_points with the ideal points of the previous call reused from `memo` (and this call's
// kept there for the next); the same candidates as without it.
std::vector<Candidate> propose_points(const MeshView& mesh, std::span<const index_t> faces, const ControlSpace& space,
                                      ProposalMemo& memo, const FarLattice& lattice = {});

// The points in the mesh as a refinement inserts them (appended to only), indexed for
// select_points' distance test. The k-d trees over the points up to some round are kept, and
// the points appended since go into one small tree of their own, until they are more than a
// quarter of the kept ones and all are indexed again: the late rounds, which add few points,
// no longer build trees over every point (serpentine lift: 0.107 s of the refinement's 0.6 s
// went to those builds). Queries answer exactly as one tree over all the points would.
class GrowingPoints {
public:
    explicit GrowingPoints(std::span<const double> xyz);  // 3 coordinates per point
    ~GrowingPoints();
    GrowingPoints(const GrowingPoints&) = delete;
    GrowingPoints& operator=(const GrowingPoints&) = delete;
    void append(std::span<const double> xyz);
    std::size_t size() const;

private:
    struct Impl;
    friend std::vector<index_t> select_points(std::span<const Candidate>, GrowingPoints&, double, const MeshView*);
    std::unique_ptr<Impl> impl_;
};

// Keeps the candidates farther than `reject_factor` * h from every point in `existing`
// and from every candidate kept before them (greedy in order, so the result does not depend
// on the thread count). Returns the kept positions in `candidates`.
// With `mesh`, whose tets' corners must all be in `existing`: a candidate with a corner of its
// holding tet (Candidate::tet) clearly within its radius is dropped without a tree query (most
// are: the same answers, for about half the queries' cost).
std::vector<index_t> select_points(std::span<const Candidate> candidates, GrowingPoints& existing,
                                   double reject_factor, const MeshView* mesh = nullptr);
// The same for points given as 3 coordinates each.
std::vector<index_t> select_points(std::span<const Candidate> candidates, std::span<const double> existing,
                                   double reject_factor, const MeshView* mesh = nullptr);

}  // namespace tubemesh::tets
