#include "engine/delaunay/triangulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "engine/delaunay/triangulation_internal.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/predicates/predicates_inline.hpp"

namespace tubemesh::delaunay {
namespace pred = tubemesh::predicates;

using namespace detail;

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
    exact_insphere += o.exact_insphere;
    exact_insphere_reused += o.exact_insphere_reused;
    seconds_passes += o.seconds_passes;
    seconds_serial += o.seconds_serial;
    return *this;
}

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
inline bool Triangulation::in_conflict(index_t tet, const double* pp, index_t p, Part& part, Scratch& s) const {
    const index_t* v = tets_.vertex(tet);
    if (is_ghost(v)) [[unlikely]]
        return ghost_in_conflict(tet, pp, p);
    const int sign = pred::detail::insphere_filter(point(v[0]), point(v[1]), point(v[2]), point(v[3]), pp);
    if (sign != 0) [[likely]]
        return sign > 0;
    return tie_in_conflict(tet, pp, p, part, s);
}

bool Triangulation::tie_in_conflict(index_t tet, const double* pp, index_t p, Part& part, Scratch& s) const {
    ++part.counters.exact_insphere;
    for (const auto& [t, in] : s.ties)
        if (t == tet) {
            ++part.counters.exact_insphere_reused;
            return in;
        }
    const index_t* v = tets_.vertex(tet);
    const index_t v0 = v[0] & ~kCavityMark;
    const bool in = pred::insphere_sos_unfiltered(point(v0), point(v[1]), point(v[2]), point(v[3]), pp, global_[v0],
                                                  global_[v[1]], global_[v[2]], global_[v[3]], global_[p]) > 0;
    s.ties.push_back({tet, in});
    return in;
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
    s.ties.clear();
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
            if (in_conflict(n, pp, p, part, s)) {
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
            const index_t outer = s.boundary[i % nb].outer;
            if (outer == kNoAdjacent) continue;  // a front face (constrained mode): no tet behind it
            sink += in_conflict(outer >> 2, pp, p, part, s);
            asm volatile("" : "+r"(sink) : : "memory");
        }
    }
#endif
    part.counters.tets_created += nb;
    ++part.counters.inserted;
    return InsertStatus::Inserted;
}

// The other source files call these hot-path templates.
template InsertStatus Triangulation::insert_one<false, false>(index_t, Part&, Scratch&);
template InsertStatus Triangulation::insert_one<false, true>(index_t, Part&, Scratch&);
template InsertStatus Triangulation::insert_one<true, false>(index_t, Part&, Scratch&);
template InsertStatus Triangulation::insert_one<true, true>(index_t, Part&, Scratch&);
template InsertStatus Triangulation::locate<false, false>(index_t, Part&, index_t&, index_t&);
template InsertStatus Triangulation::locate<false, true>(index_t, Part&, index_t&, index_t&);

}  // namespace tubemesh::delaunay
