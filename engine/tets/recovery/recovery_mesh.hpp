#pragma once
// The mutable tetrahedral mesh of boundary recovery: the kernel's TetStore itself, taken over
// from the Delaunay tetrahedralisation and handed on to the tet domain (4 rows per slot,
// neighbour 4*t + f across face f, kNoAdjacent on the box hull), plus what local modification
// needs and the kernel does not keep: one incident tet per vertex, a free-slot list, and epoch
// marks for traversals.
//
// Every modification (flip, split, contraction) is one call to replace(): remove a set of
// tets, add tets that fill the same region. replace() relinks the new tets to each other and
// to the old set's outside neighbours by matching faces, so each operation only has to say
// which tets it wants, never how the neighbour pointers change.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/delaunay/tet_store.hpp"

namespace tubemesh::tets {

// A triangle's point ids in increasing order: the key that matches a face from either side.
inline std::array<index_t, 3> sorted3(index_t a, index_t b, index_t c) {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {a, b, c};
}

using Tet = std::array<index_t, 4>;

// Epoch marks on tet slots for traversals: next() invalidates every mark. The mesh keeps its own
// for its modifications; a thread that reads the mesh while others do (nothing modifies it
// meanwhile) brings its own to ball and find_edge.
class SlotMarks {
public:
    std::uint32_t next(index_t slots);  // also grows the marks to `slots`
    bool marked(index_t t, std::uint32_t epoch) const { return mark_[t] == epoch; }
    void set(index_t t, std::uint32_t epoch) { mark_[t] = epoch; }

private:
    std::vector<std::uint32_t> mark_;
    std::uint32_t epoch_ = 0;
};

class RecoveryMesh {
public:
    // Takes over the kernel's tets over `xyz` (3 per point; box corners included).
    RecoveryMesh(std::vector<double> xyz, delaunay::TetStore&& tets);

    index_t point_count() const { return static_cast<index_t>(xyz_.size() / 3); }
    const double* point(index_t v) const { return xyz_.data() + std::size_t{3} * v; }
    const std::vector<double>& xyz() const { return xyz_; }
    // A new vertex (no tet yet: the caller splits tets with replace()).
    index_t add_point(const double* p);

    index_t slot_count() const { return tets_.size(); }
    bool alive(index_t t) const { return tets_.vertex(t)[0] != delaunay::kFreeSlot; }
    const index_t* vertex(index_t t) const { return tets_.vertex(t); }
    index_t neighbour(index_t code) const { return tets_.neighbour(code); }
    Tet tet(index_t t) const { return {vertex(t)[0], vertex(t)[1], vertex(t)[2], vertex(t)[3]}; }
    // A live tet containing v, or kNoIndex when v is in no tet.
    index_t incident_tet(index_t v) const { return incident_[v]; }

    // All live tets containing v (its ball), in a deterministic order.
    void ball(index_t v, std::vector<index_t>& out) { ball(v, out, marks_); }
    // A live tet containing both a and b, or kNoIndex.
    index_t find_edge(index_t a, index_t b) { return find_edge(a, b, slots_, marks_); }
    // The tets around edge ab and the ring of their other vertices, ordered so that tet i is
    // (a, b, ring[i], ring[i+1 mod n]) and orient3d(a, b, ring[i], ring[i+1]) > 0. False when
    // the edge is missing or on the box hull (its ring is open).
    bool edge_ring(index_t a, index_t b, std::vector<index_t>& tets, std::vector<index_t>& ring);
    // The face of tet t opposite local vertex f is a face of the mesh; its vertices with the
    // normal pointing out of t.
    std::array<index_t, 3> face(index_t t, int f) const;
    // The tets with face abc (any order) on its two sides: tet[0] where orient3d(a, b, c, d) < 0,
    // tet[1] where it is > 0, d their fourth vertex (at local[i]); kNoIndex where there is none.
    struct FaceSides {
        std::array<index_t, 2> tet{kNoIndex, kNoIndex};
        std::array<int, 2> local{-1, -1};
    };
    // The tet with edge ab, and the tets on the sides of face abc, given the ball of a (as
    // ball() lists it): callers ask about several edges or faces at a from one ball walk.
    index_t edge_in(std::span<const index_t> ball_of_a, index_t b) const;
    FaceSides face_in(std::span<const index_t> ball_of_a, index_t a, index_t b, index_t c) const;
    // ball and find_edge for concurrent readers, each with its own scratch (`around`: the
    // ball of a).
    void ball(index_t v, std::vector<index_t>& out, SlotMarks& marks) const;
    index_t find_edge(index_t a, index_t b, std::vector<index_t>& around, SlotMarks& marks) const;

    // Removes `old_tets` and adds `new_tets` (each positively oriented, checked by the caller)
    // filling the same region; new slots reuse the old ones first. Returns false, changing
    // nothing, when the new tets' faces do not pair up with each other and the old set's boundary
    // (e.g. a contraction that would glue two faces). The new tets' slots go to `added`.
    bool replace(std::span<const index_t> old_tets, std::span<const Tet> new_tets, std::vector<index_t>* added = nullptr);

    // The mesh's own epoch marks on tets (SlotMarks) for traversals.
    std::uint32_t next_epoch() { return marks_.next(slot_count()); }
    bool marked(index_t t, std::uint32_t epoch) const { return marks_.marked(t, epoch); }
    void set_mark(index_t t, std::uint32_t epoch) { marks_.set(t, epoch); }

    // The live tets with keep[t] set, moved down in slot order in the store itself (neighbours
    // renumbered, kNoAdjacent towards a dropped tet), and the store handed over: the mesh is
    // empty afterwards.
    delaunay::TetStore release(std::span<const std::uint8_t> keep);

private:
    // A new slot at the end (capacity grows by half: a pointer into the rows moves then).
    index_t append_slot();

    std::vector<double> xyz_;
    delaunay::TetStore tets_;
    std::vector<index_t> incident_;
    std::vector<index_t> free_;
    SlotMarks marks_;
    // Scratch of replace().
    struct BoundaryFace {
        std::array<index_t, 3> key;  // sorted vertex ids
        index_t outside;             // neighbour code outside the old set, or kNoAdjacent
        bool used;
    };
    std::vector<BoundaryFace> boundary_;
    std::vector<index_t> slots_;
};

}  // namespace tubemesh::tets
