#pragma once
// Local modifications of boundary recovery: the 2-3 flip, edge removal (3-2, 4-4 and the
// general n -> 2n-4 flip), point insertion into a star-shaped cavity (Steiner points) and
// point contraction (Steiner point removal). Each checks its new tets with the exact orient3d
// and changes nothing when one would be flat or inverted, when it would destroy a locked front
// edge or face, or when a new element would cross the recovery target. Flips that obey the
// last rule strictly reduce the number of elements crossing the target, so a recovery loop
// built on them terminates.
//
// These primitives do not know about recovery beyond the Target and the locks: the
// optimisation step could share them (its own flips are driven by quality instead).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/tets/recovery/front_check.hpp"
#include "engine/tets/recovery/recovery_crossings.hpp"
#include "engine/tets/recovery/recovery_mesh.hpp"

namespace tubemesh::tets {

// Front edges are never removed; front faces are not removed while lock_faces is set (the
// face-recovery phase: faces already present stay). Looked up by binary search in the sorted
// lists check_front made: only missing elements ask (few on most fronts), and hash sets of
// every edge and triangle took longer to build than all the lookups (bench/results/tuning-notes.md).
class FrontLocks {
public:
    explicit FrontLocks(const FrontElements& front) : front_(front) {}
    bool edge(index_t u, index_t v) const;
    bool face(index_t x, index_t y, index_t z) const;
    bool lock_faces = false;

private:
    const FrontElements& front_;
};

struct FlipCounters {
    std::uint64_t flips23 = 0;
    std::uint64_t edge_removals = 0;  // 3-2 (ring 3), 4-4 (ring 4) and larger
    std::uint64_t flips32 = 0;
    std::uint64_t flips44 = 0;
};

// 2-3 flip of the face opposite local vertex f of tet t. `target` may be null.
bool flip23(RecoveryMesh& m, index_t t, int f, const Target* target, const FrontLocks& locks, FlipCounters& c);

// Largest ring an edge removal can search (the size of its tables).
constexpr int kMaxRecoveryRing = 16;

// Removes edge uv: the ring of its n tets is replaced by 2n-4 tets, from the triangulation of
// the ring polygon that maximises the smallest new tet's collapse measure among those that
// are valid (ring_triangulation.hpp). Rings larger than max_ring (at most kMaxRecoveryRing)
// are not tried.
bool remove_edge(RecoveryMesh& m, index_t u, index_t v, const Target* target, const FrontLocks& locks,
                 int max_ring, FlipCounters& c);

// Inserts point p, joining it to the boundary of `cavity` (tets forming a region star-shaped
// from p). Returns the new vertex, or kNoIndex (nothing changed) when a new tet would not be
// positive or a face inside the cavity is locked.
index_t insert_point(RecoveryMesh& m, std::span<const index_t> cavity, const double* p, const FrontLocks& locks);

// Replaces the shell of edge pq, whose ring holds both ends a, b of the target segment, by
// tets around ab: the triangles (a, b, p) and (a, b, q) cut the shell in two, and each half
// is coned from one of its ring points, or from a new point inside it when none will do (the
// new points, at most 2, go to `added`). This is where flips run out on a flat front: when pq
// is ab's other diagonal in two coplanar front triangles, a ring point is often coplanar with
// p or q and a neighbour (the next front face at a front corner, a plane of a grid), so every
// triangulation of the ring needs a flat tet; and Steiner points off the plane, not joined to
// ab, only move the crossing. Changes nothing and returns false when pq or a face at pq is
// locked, a or b is not in pq's ring, or no apex gives positive tets.
bool swap_shell_to_segment(RecoveryMesh& m, index_t p, index_t q, const Target& target, const FrontLocks& locks,
                           std::vector<index_t>& added);

// Removes vertex s by moving it onto the neighbour that leaves the best smallest tet
// collapse measure, if any move leaves only positive tets. Faces not containing s survive,
// so front faces and edges are never touched.
bool contract_point(RecoveryMesh& m, index_t s);

}  // namespace tubemesh::tets
