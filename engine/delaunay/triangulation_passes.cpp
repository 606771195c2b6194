// The kernel's driver (see triangulation.hpp): the first tet, serial insertion, parallel
// passes over spatial parts, and the hand-over of the finished store.
#include "engine/delaunay/triangulation.hpp"

#include <algorithm>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "engine/delaunay/triangulation_internal.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/predicates/predicates_inline.hpp"

namespace tubemesh::delaunay {
namespace pred = tubemesh::predicates;
using namespace detail;

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
    const Vec3 u = vec3_at(pb) - vec3_at(pa);
    for (index_t q : candidates) {
        const double area2 = norm2(cross(u, vec3_at(point(q)) - vec3_at(pa)));
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
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i % kPulseEvery == kPulseEvery - 1) beat(pulse_);
        if (constrained_)
            insert_one<false, true>(points[i], part, s);
        else
            insert_one<false, false>(points[i], part, s);
    }
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
        for (std::size_t k = 0; k < pt.points.size(); ++k) {
            if (k % kPulseEvery == kPulseEvery - 1) {
                if (tbb::is_current_task_group_canceling()) return;  // another part's pulse threw
                beat(pulse_);
            }
            const index_t i = pt.points[k];
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
