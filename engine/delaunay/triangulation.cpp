#include "engine/delaunay/triangulation.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "engine/mesh/topology.hpp"
#include "engine/predicates/predicates_inline.hpp"

namespace tubemesh::delaunay {
namespace pred = tubemesh::predicates;

namespace {

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
constexpr index_t kMaxMatrixVertices = 256;

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

bool same_position(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// For an unmarked row (kCavityMark clear).
bool is_ghost(const index_t* v) {
    return v[0] == kInfiniteVertex || v[1] == kInfiniteVertex || v[2] == kInfiniteVertex || v[3] == kInfiniteVertex;
}

bool is_free(const index_t* v) { return v[0] == kFreeSlot; }
bool is_marked(const index_t* v) { return (v[0] & kCavityMark) != 0; }
void mark(index_t* v) { v[0] |= kCavityMark; }
void unmark(index_t* v) { v[0] &= ~kCavityMark; }

unsigned infinite_slot(const index_t* v) {
    return v[0] == kInfiniteVertex ? 0 : v[1] == kInfiniteVertex ? 1 : v[2] == kInfiniteVertex ? 2 : 3;
}


using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

KernelCounters& KernelCounters::operator+=(const KernelCounters& o) {
    inserted += o.inserted;
    conflicts += o.conflicts;
    walk_conflicts += o.walk_conflicts;
    no_room += o.no_room;
    walk_steps += o.walk_steps;
    tets_created += o.tets_created;
    passes += o.passes;
    serial_inserted += o.serial_inserted;
    blocked += o.blocked;
    shrunk += o.shrunk;
    seconds_passes += o.seconds_passes;
    seconds_serial += o.seconds_serial;
    return *this;
}

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
    // edge_face[la * count + lb], count = the cavity's boundary vertex count: face code of the
    // new tet whose face holds the directed boundary edge a->b. Never cleared: every entry
    // read was written for the same cavity.
    std::vector<index_t> edge_face;
    EdgeTable edges;
};

struct Triangulation::ScratchPool {
    tbb::enumerable_thread_specific<Scratch> local;
};

Triangulation::Triangulation() : scratch_(std::make_unique<ScratchPool>()) {}
Triangulation::~Triangulation() = default;

void Triangulation::reserve_points(std::size_t n) {
    xyz_.reserve(3 * n);
    global_.reserve(n);
    local_.reserve(n);
    owner_.reserve(n);
    advise_point_arrays();
}

index_t Triangulation::add_points(std::span<const double> xyz, std::span<const index_t> global_ids) {
    if (xyz.size() != 3 * global_ids.size()) throw Error("Delaunay: coordinate and id counts disagree");
    if (global_.size() + global_ids.size() >= kInfiniteVertex) throw Error("Delaunay: too many points for 32-bit ids");
    const auto first = static_cast<index_t>(global_.size());
    xyz_.insert(xyz_.end(), xyz.begin(), xyz.end());
    global_.insert(global_.end(), global_ids.begin(), global_ids.end());
    local_.resize(global_.size(), kNoIndex);
    owner_.resize(global_.size());
    if (constrained_) seed_.resize(global_.size(), kNoIndex);
    advise_point_arrays();
    note_memory();
    return first;
}

index_t Triangulation::add_points(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                  std::span<const index_t> ids) {
    if (global_.size() + ids.size() >= kInfiniteVertex) throw Error("Delaunay: too many points for 32-bit ids");
    const auto first = static_cast<index_t>(global_.size());
    xyz_.resize(xyz_.size() + 3 * ids.size());
    global_.insert(global_.end(), ids.begin(), ids.end());
    local_.resize(global_.size(), kNoIndex);
    owner_.resize(global_.size());
    double* out = xyz_.data() + std::size_t{3} * first;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 16384), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
            out[3 * k] = x[ids[k]];
            out[3 * k + 1] = y[ids[k]];
            out[3 * k + 2] = z[ids[k]];
        }
    });
    advise_point_arrays();
    note_memory();
    return first;
}

void Triangulation::set_curve_keys(std::vector<std::uint64_t> keys) {
    if (keys.size() != global_.size()) throw Error("Delaunay: one curve key per point expected");
    key_ = std::move(keys);
    note_memory();
}

// Point arrays are read at random (every tet visited reads its four vertices): huge pages
// as for the tet store. Called after every growth (a moved block loses the advice).
void Triangulation::advise_point_arrays() {
    advise_huge_pages(xyz_.data(), xyz_.capacity() * sizeof(double));
    advise_huge_pages(local_.data(), local_.capacity() * sizeof(index_t));
    advise_huge_pages(owner_.data(), owner_.capacity());
}

void Triangulation::note_memory() {
    const std::size_t bytes = tets_.bytes() + xyz_.capacity() * sizeof(double) +
                              (global_.capacity() + local_.capacity() + free_.capacity()) * sizeof(index_t) +
                              key_.capacity() * sizeof(std::uint64_t) + owner_.capacity();
    peak_bytes_ = std::max(peak_bytes_, bytes);
}

// ---------------------------------------------------------------------------------------
// Predicates on tets. Orientation is exact and unperturbed; insphere ties go to the
// symbolic perturbation with global ids.

// The common case inline: a finite tet and a filter that decides. Ties and ghosts go to
// out-of-line code.
inline bool Triangulation::in_conflict(index_t tet, const double* pp, index_t p) const {
    const index_t* v = tets_.vertex(tet);
    if (is_ghost(v)) [[unlikely]]
        return ghost_in_conflict(tet, pp, p);
    const int s = pred::detail::insphere_filter(point(v[0]), point(v[1]), point(v[2]), point(v[3]), pp);
    if (s != 0) [[likely]]
        return s > 0;
    return insphere_exact(v, pp, p) > 0;
}

// v may be the row of a cavity tet (the finite tet behind a ghost): mask its mark.
int Triangulation::insphere_exact(const index_t* v, const double* pp, index_t p) const {
    const index_t v0 = v[0] & ~kCavityMark;
    return pred::insphere_sos(point(v0), point(v[1]), point(v[2]), point(v[3]), pp, global_[v0], global_[v[1]],
                              global_[v[2]], global_[v[3]], global_[p]);
}

bool Triangulation::ghost_in_conflict(index_t tet, const double* pp, index_t p) const {
    // Does p see the hull face from outside?
    const index_t* v = tets_.vertex(tet);
    const unsigned inf = infinite_slot(v);
    const double* q[4];
    for (unsigned k = 0; k < 4; ++k) q[k] = k == inf ? pp : point(v[k]);
    const int o = pred::orient3d_inline(q[0], q[1], q[2], q[3]);
    if (o != 0) return o > 0;
    // p lies in the face's plane: in conflict when inside the face's circumcircle, which is
    // where the plane cuts the circumsphere of the finite tet behind the face.
    return insphere_exact(tets_.vertex(tets_.neighbour(4 * tet + inf) >> 2), pp, p) > 0;
}

// ---------------------------------------------------------------------------------------
// Point location: visibility walk, faces tried from a random start so it cannot cycle.
//
// In a parallel pass the walk may cross tets it does not own, but only tets that no other
// part can change: it never steps through a face whose finite vertices all belong to one
// other part (that part may rewrite the face's adjacency slot and the tet behind it). Every
// other face's slot, and every tet behind such a face, stays as it was during the pass.

template <bool kParts, bool kFront>
InsertStatus Triangulation::locate(index_t p, Part& part, index_t& tet, index_t& vertex) {
    const double* pp = point(p);
    // True when the face opposite local vertex f of v may be changed by another part.
    const auto foreign_face = [&](const index_t* v, unsigned f) {
        int other = -1;
        for (unsigned k = 0; k < 4; ++k) {
            if (k == f || v[k] == kInfiniteVertex) continue;
            const int o = owner_[v[k]];
            if (o == part.id || (other >= 0 && o != other)) return false;
            other = o;
        }
        return true;
    };
    index_t t = part.hint;
    unsigned from = 4;
    const std::uint64_t limit = std::uint64_t{tets_.size()} + 16;
    [[maybe_unused]] bool restarted = false;
    for (std::uint64_t steps = 0;; ++steps) {
        const index_t* v = tets_.vertex(t);
        const double* c[4] = {point(v[0]), point(v[1]), point(v[2]), point(v[3])};
        const std::uint32_t r = part.random();
        unsigned exit = 4;
        [[maybe_unused]] unsigned front_exit = 4;
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned f = (r + k) & 3;
            if (f == from) continue;
            const double* q[4] = {c[0], c[1], c[2], c[3]};
            q[f] = pp;
            if (pred::orient3d_inline(q[0], q[1], q[2], q[3]) < 0) {
                if constexpr (kFront) {
                    // Prefer a way round a concave part of the front to running into it.
                    if (tets_.neighbour(4 * t + f) == kNoAdjacent) {
                        front_exit = f;
                        continue;
                    }
                }
                exit = f;
                break;
            }
        }
        if constexpr (kFront) {
            if (exit == 4 && front_exit != 4) {
                // p lies beyond a front face of t: outside the region, or the walk ran into a
                // concave part of the front. A parallel part retries later; a serial walk
                // starts once more from the tet the caller named near p.
                tet = t;
                if constexpr (kParts) return InsertStatus::Conflict;
                const index_t seed = seed_[p];
                if (restarted || seed == kNoIndex || seed >= tets_.size() || is_free(tets_.vertex(seed)))
                    return InsertStatus::Blocked;
                restarted = true;
                t = seed;
                from = 4;
                steps = 0;
                continue;
            }
        }
        if (exit == 4) break;
        if constexpr (kParts) {
            if (foreign_face(v, exit)) return InsertStatus::Conflict;
        }
        const index_t code = tets_.neighbour(4 * t + exit);
        t = code >> 2;
        from = code & 3;
        ++part.counters.walk_steps;
        if constexpr (kFront) {
            // Off Delaunay meshes a visibility walk may circle; give the point up rather than fail.
            if (steps > limit) {
                tet = t;
                return kParts ? InsertStatus::Conflict : InsertStatus::Blocked;
            }
            continue;
        }
        if (is_ghost(tets_.vertex(t))) break;  // p is outside the hull, beyond this face
        if (steps > limit) throw Error("Delaunay: point location did not terminate (internal error)");
    }
    tet = t;
    const index_t* v = tets_.vertex(t);
    if (!is_ghost(v))
        for (unsigned k = 0; k < 4; ++k)
            if (same_position(point(v[k]), pp)) {
                vertex = v[k];
                return InsertStatus::Duplicate;
            }
    if constexpr (kParts) {
        for (unsigned k = 0; k < 4; ++k)
            if (v[k] != kInfiniteVertex && owner_[v[k]] != part.id) return InsertStatus::Conflict;
    }
    return InsertStatus::Inserted;
}

bool Triangulation::take_slots(Part& part, std::size_t n, std::vector<index_t>& out) {
    const std::size_t from_free = std::min(n, part.free.size());
    const std::size_t from_bump = n - from_free;
    if (from_bump > std::size_t{part.end - part.next}) {
        if (!part.growable) return false;
        const std::size_t want = std::max<std::size_t>(std::size_t{tets_.capacity()} * 3 / 2,
                                                       std::size_t{part.next} + from_bump + 1024);
        tets_.reserve(std::min(want, kMaxTets));
        if (from_bump > std::size_t{tets_.capacity() - part.next}) throw Error("Delaunay: too many tetrahedra");
        part.end = tets_.capacity();
        note_memory();
    }
    for (std::size_t k = 0; k < from_free; ++k) {
        out.push_back(part.free.back());
        part.free.pop_back();
    }
    for (std::size_t k = 0; k < from_bump; ++k) out.push_back(part.next++);
    if (part.growable) tets_.set_size(part.next);
    return true;
}

// ---------------------------------------------------------------------------------------
// Adjacency among the new tets. Seen from outside the cavity its boundary is a closed,
// consistently oriented surface, so the new tets on the two sides of a boundary edge hold
// it in opposite directions: the tet whose face (in kTetTopology order) runs a->b meets the
// tet whose face runs b->a, across the face opposite each face's third vertex.

void Triangulation::link_new_tets(Scratch& s) {
    index_t count = 0;
    index_t infinite_local = kNoIndex;
    const auto local_id = [&](index_t v) {
        index_t& l = v == kInfiniteVertex ? infinite_local : local_[v];
        if (l == kNoIndex) {
            l = count++;
            s.boundary_vertices.push_back(v);
        }
        return l;
    };
    s.boundary_vertices.clear();
    for (BoundaryFace& b : s.boundary) {
        const auto& node = kTetTopology.face[b.face].node;
        for (int k = 0; k < 3; ++k) b.local[k] = local_id(b.v[node[k]]);
    }
    if (count <= kMaxMatrixVertices) {
        if (s.edge_face.size() < std::size_t{count} * count) s.edge_face.resize(std::size_t{count} * count);
        index_t* m = s.edge_face.data();  // count x count, row = edge start
        for (const BoundaryFace& b : s.boundary) {
            const auto& node = kTetTopology.face[b.face].node;
            for (int k = 0; k < 3; ++k) m[b.local[k] * count + b.local[(k + 1) % 3]] = 4 * b.slot + node[(k + 2) % 3];
        }
        for (const BoundaryFace& b : s.boundary) {
            const auto& node = kTetTopology.face[b.face].node;
            for (int k = 0; k < 3; ++k)
                tets_.neighbour(4 * b.slot + node[(k + 2) % 3]) = m[b.local[(k + 1) % 3] * count + b.local[k]];
        }
    } else {
        s.edges.begin(s.boundary.size() * 3 / 2);
        for (const BoundaryFace& b : s.boundary) {
            const auto& node = kTetTopology.face[b.face].node;
            for (int k = 0; k < 3; ++k) {
                index_t u = b.local[k], w = b.local[(k + 1) % 3];
                if (u > w) std::swap(u, w);
                const index_t code = 4 * b.slot + node[(k + 2) % 3];
                const index_t other = s.edges.match(std::uint64_t{u} << 32 | w, code);
                if (other != kNoIndex) {
                    tets_.neighbour(code) = other;
                    tets_.neighbour(other) = code;
                }
            }
        }
    }
    for (index_t v : s.boundary_vertices)
        if (v != kInfiniteVertex) local_[v] = kNoIndex;
}

// ---------------------------------------------------------------------------------------
// Bowyer-Watson insertion of one point.

template <bool kParts, bool kFront>
InsertStatus Triangulation::insert_one(index_t p, Part& part, Scratch& s) {
    index_t start = kNoIndex, same = kNoIndex;
    const InsertStatus located = locate<kParts, kFront>(p, part, start, same);
    if (located == InsertStatus::Duplicate) {
        part.duplicates.emplace_back(p, same);
        return located;
    }
    if constexpr (kFront) {
        if (located == InsertStatus::Blocked) {
            part.blocked.push_back(p);
            ++part.counters.blocked;
            return located;
        }
    }
    if (located != InsertStatus::Inserted) {
        ++part.counters.conflicts;
        ++part.counters.walk_conflicts;
        return located;
    }

    const double* pp = point(p);
    s.cavity.clear();
    s.boundary.clear();
    mark(tets_.vertex(start));
    s.cavity.push_back(start);
    bool left_part = false;
    for (std::size_t i = 0; i < s.cavity.size() && !left_part; ++i) {
        const index_t c = s.cavity[i];
        const index_t* cv = tets_.vertex(c);
        // The four neighbours are independent cache misses: start them all at once.
        for (unsigned f = 0; f < 4; ++f) __builtin_prefetch(tets_.vertex(tets_.neighbour(4 * c + f) >> 2));
        for (unsigned f = 0; f < 4; ++f) {
            const index_t code = tets_.neighbour(4 * c + f);
            if constexpr (kFront) {
                if (code == kNoAdjacent) {  // a front face: the cavity stops here
                    s.boundary.push_back({{cv[0] & ~kCavityMark, cv[1], cv[2], cv[3]}, code, f, c});
                    continue;
                }
            }
            const index_t n = code >> 2;
            if (is_marked(tets_.vertex(n))) continue;
            if (in_conflict(n, pp, p)) {
                if constexpr (kParts) {
                    // n shares a face with an owned tet: only its opposite vertex can be foreign.
                    const index_t w = tets_.vertex(n)[code & 3];
                    if (w != kInfiniteVertex && owner_[w] != part.id) {
                        left_part = true;
                        break;
                    }
                }
                mark(tets_.vertex(n));
                s.cavity.push_back(n);
            } else {
                // slot: the cavity tet, for shrink_to_visible (overwritten below).
                s.boundary.push_back({{cv[0] & ~kCavityMark, cv[1], cv[2], cv[3]}, code, f, kFront ? c : index_t{0}});
            }
        }
    }
    if constexpr (kFront) {
        if (!left_part) {
            const std::size_t before = s.cavity.size();
            if (!shrink_to_visible(p, start, s)) {
                for (index_t c : s.cavity) unmark(tets_.vertex(c));
                part.blocked.push_back(p);
                ++part.counters.blocked;
                return InsertStatus::Blocked;
            }
            if (s.cavity.size() != before) ++part.counters.shrunk;
        }
    }

    const std::size_t nc = s.cavity.size(), nb = s.boundary.size();
    s.extra.clear();
    if (left_part || (nb > nc && !take_slots(part, nb - nc, s.extra))) {
        for (index_t c : s.cavity) unmark(tets_.vertex(c));
        if (left_part) {
            ++part.counters.conflicts;
            return InsertStatus::Conflict;
        }
        ++part.counters.no_room;
        return InsertStatus::NoRoom;
    }

    // One new tet per boundary face: the doomed tet with the face's far vertex replaced by
    // p (p sees the face from the same side), so local face numbers carry over.
    index_t hint = kNoIndex;
    for (std::size_t i = 0; i < nb; ++i) {
        BoundaryFace& b = s.boundary[i];
        b.slot = i < nc ? s.cavity[i] : s.extra[i - nc];
        index_t* nv = tets_.vertex(b.slot);
        nv[0] = b.v[0];
        nv[1] = b.v[1];
        nv[2] = b.v[2];
        nv[3] = b.v[3];
        nv[b.face] = p;
        if (!is_ghost(nv)) hint = b.slot;
        const index_t self = 4 * b.slot + b.face;
        tets_.neighbour(self) = b.outer;
        if (!kFront || b.outer != kNoAdjacent) tets_.neighbour(b.outer) = self;
    }
    link_new_tets(s);
    for (std::size_t i = nb; i < nc; ++i) {
        tets_.vertex(s.cavity[i])[0] = kFreeSlot;
        part.free.push_back(s.cavity[i]);
    }
    part.hint = hint;
    part.net_slots += static_cast<std::int64_t>(nb) - static_cast<std::int64_t>(nc);
#ifdef TUBEMESH_BENCH_SLOWDOWN
    // Only for the test of the benchmark gate (CMake option TUBEMESH_BENCH_SLOWDOWN, off by
    // default): redo some of the boundary's conflict tests, real work that makes an insertion
    // about TUBEMESH_BENCH_SLOWDOWN percent slower in time and in instructions.
    {
        unsigned sink = 0;
        const std::size_t redo = nb * TUBEMESH_BENCH_SLOWDOWN / 50;
        for (std::size_t i = 0; i < redo; ++i) {
            sink += in_conflict(s.boundary[i % nb].outer >> 2, pp, p);
            asm volatile("" : "+r"(sink) : : "memory");
        }
    }
#endif
    part.counters.tets_created += nb;
    ++part.counters.inserted;
    return InsertStatus::Inserted;
}

// ---------------------------------------------------------------------------------------
// Constrained mode: taking over a mesh, and cavities made star-shaped.

void Triangulation::adopt(std::span<const double> xyz, TetStore&& tets) {
    if (started()) throw Error("Delaunay: adopt() on a triangulation that already has tets");
    if (xyz.size() % 3 != 0) throw Error("Delaunay: adopt() needs 3 coordinates per point");
    if (tets.size() == 0) throw Error("Delaunay: adopt() needs a mesh with at least one tetrahedron");
    const auto n = static_cast<index_t>(xyz.size() / 3);
    if (n >= kInfiniteVertex) throw Error("Delaunay: too many points for 32-bit ids");
    constrained_ = true;
    xyz_.assign(xyz.begin(), xyz.end());
    global_.resize(n);
    for (index_t v = 0; v < n; ++v) global_[v] = v;
    local_.assign(n, kNoIndex);
    owner_.assign(n, 0);
    seed_.assign(n, kNoIndex);
    tets_ = std::move(tets);
    hint_ = 0;
    note_memory();
}

// The new tet on boundary face b is the cavity tet with b's far vertex replaced by p: it has a
// positive volume exactly when p sees b from inside the cavity. Shrinking drops the cavity tet
// behind the first face p does not see and keeps what is still connected to `start`; every
// round drops a tet, so it ends.
bool Triangulation::shrink_to_visible(index_t p, index_t start, Scratch& s) {
    const double* pp = point(p);
    const auto sees = [&](const BoundaryFace& b) {
        const double* q[4] = {point(b.v[0]), point(b.v[1]), point(b.v[2]), point(b.v[3])};
        q[b.face] = pp;
        return pred::orient3d_inline(q[0], q[1], q[2], q[3]) > 0;
    };
    for (;;) {
        index_t drop = kNoIndex;
        for (const BoundaryFace& b : s.boundary)
            if (!sees(b)) {
                drop = b.slot;
                break;
            }
        if (drop == kNoIndex) return true;
        if (drop == start) return false;
        s.kept.clear();
        for (index_t c : s.cavity) {
            unmark(tets_.vertex(c));
            if (c != drop) s.kept.push_back(c);
        }
        std::sort(s.kept.begin(), s.kept.end());
        s.cavity.clear();
        s.boundary.clear();
        mark(tets_.vertex(start));
        s.cavity.push_back(start);
        for (std::size_t i = 0; i < s.cavity.size(); ++i) {
            const index_t c = s.cavity[i];
            const index_t* cv = tets_.vertex(c);
            for (unsigned f = 0; f < 4; ++f) {
                const index_t code = tets_.neighbour(4 * c + f);
                if (code != kNoAdjacent) {
                    const index_t n = code >> 2;
                    if (is_marked(tets_.vertex(n))) continue;
                    if (std::binary_search(s.kept.begin(), s.kept.end(), n)) {
                        mark(tets_.vertex(n));
                        s.cavity.push_back(n);
                        continue;
                    }
                }
                s.boundary.push_back({{cv[0] & ~kCavityMark, cv[1], cv[2], cv[3]}, code, f, c});
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The first tet and its four ghosts.

std::vector<index_t> Triangulation::start(std::span<const index_t> candidates) {
    if (started()) throw Error("Delaunay: start() called twice");
    if (candidates.size() < 4) return {};
    const index_t a = candidates[0];
    const double* pa = point(a);
    index_t b = kNoIndex;
    for (index_t q : candidates)
        if (!same_position(point(q), pa)) {
            b = q;
            break;
        }
    if (b == kNoIndex) return {};
    const double* pb = point(b);
    // The third point: farthest from the line ab, so "not collinear" is not a rounding artefact.
    index_t c = kNoIndex;
    double best = 0;
    const double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    for (index_t q : candidates) {
        const double* pq = point(q);
        const double w[3] = {pq[0] - pa[0], pq[1] - pa[1], pq[2] - pa[2]};
        const double cx = u[1] * w[2] - u[2] * w[1], cy = u[2] * w[0] - u[0] * w[2], cz = u[0] * w[1] - u[1] * w[0];
        const double area2 = cx * cx + cy * cy + cz * cz;
        if (area2 > best) {
            best = area2;
            c = q;
        }
    }
    if (c == kNoIndex) return {};
    index_t d = kNoIndex;
    for (index_t q : candidates)
        if (pred::orient3d(pa, pb, point(c), point(q)) != 0) {
            d = q;
            break;
        }
    if (d == kNoIndex) return {};

    index_t v[4] = {a, b, c, d};
    if (pred::orient3d(point(a), point(b), point(c), point(d)) < 0) std::swap(v[0], v[1]);
    tets_.reserve(std::max<std::size_t>(tets_.capacity(), 64));
    tets_.set_size(5);
    std::copy(v, v + 4, tets_.vertex(0));
    // Ghost f: the tet with vertex f replaced by infinity, two others swapped so that
    // infinity, standing for a far point beyond face f, gives a positive orientation.
    for (unsigned f = 0; f < 4; ++f) {
        index_t* g = tets_.vertex(1 + f);
        std::copy(v, v + 4, g);
        g[f] = kInfiniteVertex;
        const unsigned s0 = (f + 1) & 3, s1 = (f + 2) & 3;
        std::swap(g[s0], g[s1]);
    }
    // Adjacency by matching vertex sets of faces (five tets: brute force is fine).
    for (index_t t = 0; t < 5; ++t)
        for (unsigned f = 0; f < 4; ++f) {
            std::array<index_t, 3> key{};
            for (unsigned k = 0, m = 0; k < 4; ++k)
                if (k != f) key[m++] = tets_.vertex(t)[k];
            std::sort(key.begin(), key.end());
            for (index_t t2 = 0; t2 < 5; ++t2)
                for (unsigned f2 = 0; f2 < 4 && t2 != t; ++f2) {
                    std::array<index_t, 3> key2{};
                    for (unsigned k = 0, m = 0; k < 4; ++k)
                        if (k != f2) key2[m++] = tets_.vertex(t2)[k];
                    std::sort(key2.begin(), key2.end());
                    if (key == key2) tets_.neighbour(4 * t + f) = 4 * t2 + f2;
                }
        }
    hint_ = 0;
    note_memory();
    return {v[0], v[1], v[2], v[3]};
}

// ---------------------------------------------------------------------------------------
// Batches: parallel passes over parts, then the stragglers serially.

void Triangulation::insert_serial(std::span<const index_t> points) {
    if (points.empty()) return;
    const auto t0 = Clock::now();
    Part part;
    part.free.swap(free_);
    part.next = tets_.size();
    part.end = tets_.capacity();
    part.growable = true;
    part.hint = hint_;
    Scratch& s = scratch_->local.local();
    if (constrained_)
        for (index_t p : points) insert_one<false, true>(p, part, s);
    else
        for (index_t p : points) insert_one<false, false>(p, part, s);
    free_.swap(part.free);
    blocked_.insert(blocked_.end(), part.blocked.begin(), part.blocked.end());
    tets_.set_size(part.next);
    hint_ = part.hint;
    duplicates_.insert(duplicates_.end(), part.duplicates.begin(), part.duplicates.end());
    part.counters.serial_inserted = part.counters.inserted;
    part.counters.seconds_serial = seconds_since(t0);
    counters_ += part.counters;
    note_memory();
}

index_t Triangulation::find_start(Part& part, index_t first_point, Scratch& s) {
    const auto owns_tet = [&](index_t t) {
        const index_t* v = tets_.vertex(t);
        const index_t v0 = v[0] & ~kCavityMark;
        if (is_ghost(v) || v0 == kInfiniteVertex) return false;
        return owner_[v0] == part.id && owner_[v[1]] == part.id && owner_[v[2]] == part.id && owner_[v[3]] == part.id;
    };
    Part walker;
    walker.hint = hint_;
    index_t t = kNoIndex, same = kNoIndex;
    if (constrained_)
        locate<false, true>(first_point, walker, t, same);  // where the walk stopped, even if blocked
    else
        locate<false, false>(first_point, walker, t, same);
    if (is_ghost(tets_.vertex(t))) t = tets_.neighbour(4 * t + infinite_slot(tets_.vertex(t))) >> 2;
    // Breadth-first from there to the nearest owned tet.
    std::vector<index_t>& seen = s.cavity;
    seen.clear();
    seen.push_back(t);
    mark(tets_.vertex(t));
    index_t found = kNoIndex;
    for (std::size_t i = 0; i < seen.size() && i < 4096 && found == kNoIndex; ++i) {
        if (owns_tet(seen[i])) found = seen[i];
        for (unsigned f = 0; f < 4; ++f) {
            const index_t code = tets_.neighbour(4 * seen[i] + f);
            if (code == kNoAdjacent) continue;  // a front face (constrained mode)
            const index_t n = code >> 2;
            if (is_marked(tets_.vertex(n)) || is_ghost(tets_.vertex(n))) continue;
            mark(tets_.vertex(n));
            seen.push_back(n);
        }
    }
    for (index_t x : seen) unmark(tets_.vertex(x));
    return found;
}

std::vector<index_t> Triangulation::insert_pass(std::span<const index_t> points, unsigned parts, int axis) {
    const auto t0 = Clock::now();
    const std::size_t m = points.size();
    const index_t nv = point_count();
    std::vector<Part> part(parts);
    if (axis < 0) {
        // Ranges of the Hilbert curve with equal point counts. `points` follow the curve
        // (forwards or backwards), so a part's points are one stretch of it and each walk
        // starts next to its target.
        std::vector<std::uint64_t> split(parts - 1);
        for (unsigned k = 1; k < parts; ++k) split[k - 1] = key_[points[m * k / parts]];
        std::sort(split.begin(), split.end());
        tbb::parallel_for(tbb::blocked_range<index_t>(0, nv, 16384), [&](const tbb::blocked_range<index_t>& r) {
            for (index_t v = r.begin(); v < r.end(); ++v)
                owner_[v] = static_cast<std::uint8_t>(std::upper_bound(split.begin(), split.end(), key_[v]) - split.begin());
        });
    } else {
        // Slabs along `axis` with equal point counts.
        std::vector<double> cut(parts - 1);
        std::vector<double> coord(m);
        for (std::size_t i = 0; i < m; ++i) coord[i] = point(points[i])[axis];
        auto from = coord.begin();
        for (unsigned k = 1; k < parts; ++k) {
            const auto at = coord.begin() + static_cast<std::ptrdiff_t>(m * k / parts);
            std::nth_element(from, at, coord.end());
            cut[k - 1] = *at;
            from = at;
        }
        tbb::parallel_for(tbb::blocked_range<index_t>(0, nv, 16384), [&](const tbb::blocked_range<index_t>& r) {
            for (index_t v = r.begin(); v < r.end(); ++v)
                owner_[v] = static_cast<std::uint8_t>(std::upper_bound(cut.begin(), cut.end(), point(v)[axis]) - cut.begin());
        });
    }
    for (unsigned k = 0; k < parts; ++k) {
        part[k].id = static_cast<std::uint8_t>(k);
        part[k].rng = (0x9e3779b9u * (k + 1) ^ static_cast<std::uint32_t>(counters_.passes)) | 1u;
    }
    for (std::size_t i = 0; i < m; ++i) part[owner_[points[i]]].points.push_back(static_cast<index_t>(i));

    // Slot quotas, fixed before the pass so slot numbers do not depend on timing: the
    // expected need plus a margin for the spread of the mean, free slots shared evenly
    // (reused slots are already paged in, fresh ones are not).
    std::size_t top = tets_.size();
    const std::size_t free_share = free_.size() / parts;
    for (Part& pt : part) {
        const double mean = double(pt.points.size()) * std::max(growth_, 6.0);
        const auto quota = static_cast<std::size_t>(mean * (1.01 + 4.0 / std::sqrt(double(pt.points.size()) + 1.0))) + 256;
        const std::size_t reuse = std::min(quota, free_share);
        pt.free.assign(free_.end() - static_cast<std::ptrdiff_t>(reuse), free_.end());
        free_.resize(free_.size() - reuse);
        pt.next = static_cast<index_t>(top);
        top += quota - reuse;
        pt.end = static_cast<index_t>(std::min(top, kMaxTets));
    }
    tets_.reserve(top);
    tets_.set_size(static_cast<index_t>(std::min(top, kMaxTets)));
    note_memory();

    Scratch& serial_scratch = scratch_->local.local();
    for (Part& pt : part)
        if (!pt.points.empty()) pt.hint = find_start(pt, points[pt.points.front()], serial_scratch);

    tbb::parallel_for(0u, parts, 1u, [&](unsigned k) {
        Part& pt = part[k];
        if (pt.hint == kNoIndex) {
            pt.failed = pt.points;
            pt.counters.conflicts += pt.points.size();
            return;
        }
        Scratch& s = scratch_->local.local();
        for (index_t i : pt.points) {
            const InsertStatus st = constrained_ ? insert_one<true, true>(points[i], pt, s)
                                                 : insert_one<true, false>(points[i], pt, s);
            if (st == InsertStatus::Conflict || st == InsertStatus::NoRoom) pt.failed.push_back(i);
        }
    });

    std::vector<index_t> failed;
    std::int64_t net = 0;
    std::uint64_t inserted = 0;
    for (Part& pt : part) {
        for (index_t t = pt.next; t < pt.end; ++t) {
            tets_.vertex(t)[0] = kFreeSlot;
            free_.push_back(t);
        }
        free_.insert(free_.end(), pt.free.begin(), pt.free.end());
        duplicates_.insert(duplicates_.end(), pt.duplicates.begin(), pt.duplicates.end());
        blocked_.insert(blocked_.end(), pt.blocked.begin(), pt.blocked.end());
        failed.insert(failed.end(), pt.failed.begin(), pt.failed.end());
        counters_ += pt.counters;
        net += pt.net_slots;
        inserted += pt.counters.inserted;
        if (pt.hint != kNoIndex) hint_ = pt.hint;
    }
    ++counters_.passes;
    if (inserted > 1000) growth_ = double(net) / double(inserted);
    std::sort(failed.begin(), failed.end());
    for (index_t& i : failed) i = points[i];
    note_memory();
    counters_.seconds_passes += seconds_since(t0);
    return failed;
}

void Triangulation::insert(std::span<const index_t> points, unsigned parts, index_t min_points_per_part) {
    if (!started()) throw Error("Delaunay: insert() before start()");
    parts = std::min(parts, 255u);
    const std::size_t min_pass = std::size_t{std::max(parts, 1u)} * std::max<index_t>(min_points_per_part, 1);
    if (parts <= 1 || points.size() < min_pass) {
        insert_serial(points);
        return;
    }
    // The first pass follows the curve when there is one. The points a pass leaves behind
    // lie along its part borders, a thin layer: the next pass cuts slabs across the layer's
    // longest extent.
    const bool curve = key_.size() == point_count();
    std::vector<index_t> todo(points.begin(), points.end());
    for (int pass = 0; todo.size() >= min_pass; ++pass) {
        int axis = -1;
        if (pass > 0 || !curve) {
            double lo[3], hi[3];
            for (int a = 0; a < 3; ++a) lo[a] = hi[a] = point(todo[0])[a];
            for (index_t p : todo)
                for (int a = 0; a < 3; ++a) {
                    lo[a] = std::min(lo[a], point(p)[a]);
                    hi[a] = std::max(hi[a], point(p)[a]);
                }
            axis = 0;
            for (int a = 1; a < 3; ++a)
                if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
        }
        std::vector<index_t> failed = insert_pass(todo, parts, axis);
        const bool stalled = failed.size() * 2 > todo.size();
        todo.swap(failed);
        if (stalled) break;
    }
    insert_serial(todo);
}

// ---------------------------------------------------------------------------------------
// Hand-over: drop ghosts and free slots, fill the holes from the end, global vertex ids.

TetStore Triangulation::finish() {
    const index_t n = tets_.size();
    const auto hole = [&](index_t t) { return is_free(tets_.vertex(t)) || is_ghost(tets_.vertex(t)); };
    tbb::parallel_for(tbb::blocked_range<index_t>(0, n, 1 << 14), [&](const tbb::blocked_range<index_t>& r) {
        for (index_t t = r.begin(); t < r.end(); ++t) {
            const index_t* v = tets_.vertex(t);
            if (is_free(v) || !is_ghost(v)) continue;
            tets_.neighbour(tets_.neighbour(4 * t + infinite_slot(v))) = kNoAdjacent;
        }
    });
    // [0, lo) live, [hi, n) holes or moved away; move the last live tet into the first hole.
    index_t lo = 0, hi = n;
    for (;;) {
        while (lo < hi && !hole(lo)) ++lo;
        while (hi > lo && hole(hi - 1)) --hi;
        if (lo >= hi) break;
        const index_t from = hi - 1;
        std::copy(tets_.vertex(from), tets_.vertex(from) + 4, tets_.vertex(lo));
        for (unsigned f = 0; f < 4; ++f) {
            const index_t code = tets_.neighbour(4 * from + f);
            tets_.neighbour(4 * lo + f) = code;
            if (code != kNoAdjacent) tets_.neighbour(code) = 4 * lo + f;
        }
        tets_.vertex(from)[0] = kFreeSlot;
        --hi;
    }
    tets_.set_size(hi);
    index_t* v = tets_.vertex(0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, std::size_t{4} * hi, 1 << 16),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i) v[i] = global_[v[i]];
                      });
    for (auto& [dup, kept] : duplicates_) {
        dup = global_[dup];
        kept = global_[kept];
    }
    std::sort(duplicates_.begin(), duplicates_.end());
    tets_.shrink_to_fit();
    free_.clear();
    free_.shrink_to_fit();
    hint_ = kNoIndex;
    TetStore out = std::move(tets_);
    tets_ = TetStore();
    return out;
}

}  // namespace tubemesh::delaunay
