#pragma once
// Internals of the Delaunay kernel shared by its three source files (triangulation.cpp: points,
// predicates, walk and cavity insertion; triangulation_passes.cpp: first tet, serial and
// parallel passes, hand-over; constrained_cavity.cpp: adopted meshes and star-shaped
// cavities). Not for use outside engine/delaunay/.
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "engine/core/timing.hpp"
#include "engine/delaunay/triangulation.hpp"

namespace tubemesh::delaunay::detail {

// A face of the cavity's boundary: the doomed tet's vertices (copied, its slot is reused),
// the face index in it and the face code of the tet outside; then the new tet's slot and
// the local ids of the face's vertices (in kTetTopology order) for linking.
struct BoundaryFace {
    index_t v[4];
    index_t outer;
    index_t face;
    index_t slot;
    index_t local[3];
};

// Boundary vertex counts up to this link through a dense matrix, larger cavities through
// the hash table.
inline constexpr index_t kMaxMatrixVertices = 256;

// Pairs up the new tets' faces around the cavity's boundary edges. Each boundary edge is
// met exactly twice; stamps replace clearing between insertions.
class EdgeTable {
public:
    void begin(std::size_t edges) {
        std::size_t size = 64;
        while (size < 2 * edges) size *= 2;
        if (size > slots_.size()) {
            slots_.assign(size, Slot{});
            mask_ = size - 1;
            stamp_ = 0;
        }
        if (++stamp_ == 0) {
            for (Slot& s : slots_) s.stamp = 0;
            stamp_ = 1;
        }
    }
    // Returns the face code stored under `key` by the other tet, or kNoIndex after storing
    // `code` for it.
    index_t match(std::uint64_t key, index_t code) {
        std::size_t h = static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ULL) >> 32) & mask_;
        for (;; h = (h + 1) & mask_) {
            Slot& s = slots_[h];
            if (s.stamp != stamp_) {
                s = {key, code, stamp_};
                return kNoIndex;
            }
            if (s.key == key) return s.code;
        }
    }

private:
    struct Slot {
        std::uint64_t key = 0;
        index_t code = 0;
        std::uint32_t stamp = 0;
    };
    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::uint32_t stamp_ = 0;
};

inline bool same_position(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// For an unmarked row (kCavityMark clear).
inline bool is_ghost(const index_t* v) {
    return v[0] == kInfiniteVertex || v[1] == kInfiniteVertex || v[2] == kInfiniteVertex || v[3] == kInfiniteVertex;
}

inline bool is_free(const index_t* v) { return v[0] == kFreeSlot; }
inline bool is_marked(const index_t* v) { return (v[0] & kCavityMark) != 0; }
inline void mark(index_t* v) { v[0] |= kCavityMark; }
inline void unmark(index_t* v) { v[0] &= ~kCavityMark; }

inline unsigned infinite_slot(const index_t* v) {
    return v[0] == kInfiniteVertex ? 0 : v[1] == kInfiniteVertex ? 1 : v[2] == kInfiniteVertex ? 2 : 3;
}

}  // namespace tubemesh::delaunay::detail

namespace tubemesh::delaunay {

using detail::BoundaryFace;
using detail::EdgeTable;

// Cache-line aligned: parts sit side by side in a vector, and each updates its counters,
// hint and allocation cursor on every insertion.
struct alignas(64) Triangulation::Part {
    // Region: the finite vertices v with owner_[v] == id (all of them for a serial part).
    std::uint8_t id = 0;
    // Slots: the free list first, then [next, end). A growable part may enlarge the store.
    std::vector<index_t> free;
    index_t next = 0, end = 0;
    bool growable = false;
    index_t hint = kNoIndex;
    std::uint32_t rng = 0x2545f491u;
    std::vector<index_t> points;  // positions in the pass's point list
    std::vector<index_t> failed;  // positions postponed to the next pass
    std::vector<std::pair<index_t, index_t>> duplicates;
    std::vector<index_t> blocked;  // constrained mode: points skipped for good
    std::int64_t net_slots = 0;  // slots taken minus slots freed
    KernelCounters counters;

    std::uint32_t random() {
        rng ^= rng << 13;
        rng ^= rng >> 17;
        rng ^= rng << 5;
        return rng;
    }
};

struct Triangulation::Scratch {
    std::vector<index_t> cavity;
    std::vector<BoundaryFace> boundary;
    std::vector<index_t> extra;
    std::vector<index_t> boundary_vertices;
    std::vector<index_t> kept;  // constrained mode: the cavity while it is shrunk, sorted
    // The current cavity's exact insphere answers (tet, in conflict): a tet outside the cavity
    // is tested once from each cavity tet beside it, and a co-spherical tie costs the exact
    // determinant and the perturbation each time.
    std::vector<std::pair<index_t, bool>> ties;
    // edge_face[la * count + lb], count = the cavity's boundary vertex count: face code of the
    // new tet whose face holds the directed boundary edge a->b. Never cleared: every entry
    // read was written for the same cavity.
    std::vector<index_t> edge_face;
    EdgeTable edges;
};

struct Triangulation::ScratchPool {
    tbb::enumerable_thread_specific<Scratch> local;
};

}  // namespace tubemesh::delaunay
