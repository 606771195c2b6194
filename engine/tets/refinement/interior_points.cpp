#include "engine/tets/refinement/interior_points.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_sort.h>

#include "engine/core/ordered_compact.hpp"
#include "engine/core/uninit_vector.hpp"
#include "engine/mesh/point_index.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/predicates/predicates_inline.hpp"
#include "engine/sizing/control_space.hpp"

namespace tubemesh::tets {
namespace pred = tubemesh::predicates;
using delaunay::kFreeSlot;
using delaunay::kNoAdjacent;

namespace {

Vec3 at(const MeshView& m, index_t v) { return {m.xyz[3 * std::size_t{v}], m.xyz[3 * std::size_t{v} + 1], m.xyz[3 * std::size_t{v} + 2]}; }
const double* ptr(const MeshView& m, index_t v) { return m.xyz.data() + 3 * std::size_t{v}; }

// Visibility walk from `tet` to p. kNoIndex when it leaves through the front (p outside, or
// behind a concave part of the front: either way no place for an ideal point of this tet)
// or circles (possible off Delaunay meshes). The face order comes from a hash, not a shared
// generator, so the walk is the same whatever thread runs it.
index_t walk_to(const MeshView& m, index_t tet, const double* p, std::uint32_t seed) {
    unsigned from = 4;
    for (int steps = 0; steps < 4096; ++steps) {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        const index_t* v = m.tets.vertex(tet);
        unsigned exit = 4;
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned f = (seed + k) & 3;
            if (f == from) continue;
            const double* q[4] = {ptr(m, v[0]), ptr(m, v[1]), ptr(m, v[2]), ptr(m, v[3])};
            q[f] = p;
            if (pred::orient3d_inline(q[0], q[1], q[2], q[3]) < 0) {
                exit = f;
                break;
            }
        }
        if (exit == 4) return tet;
        const index_t code = m.tets.neighbour(4 * tet + exit);
        if (code == kNoAdjacent) return kNoIndex;
        tet = code >> 2;
        from = code & 3;
    }
    return kNoIndex;
}

// The node of the body-centred cubic lattice with cube edge a (a corner at the origin) nearest p.
Vec3 nearest_bcc_node(const Vec3& p, double a) {
    const Vec3 corner{a * std::round(p.x / a), a * std::round(p.y / a), a * std::round(p.z / a)};
    const Vec3 centre{a * (std::floor(p.x / a) + 0.5), a * (std::floor(p.y / a) + 0.5), a * (std::floor(p.z / a) + 0.5)};
    return distance2(p, corner) <= distance2(p, centre) ? corner : centre;
}

// The lattice node moved by a fixed, tiny offset (kLatticeJitter of the cube edge at most per
// axis) drawn from a hash of the node: a lattice's points are co-spherical by the dozen, and
// every such exact tie costs the kernel the exact insphere and the symbolic perturbation, while
// ties this far from exact are decided by the floating-point filter. The same node always gets
// the same offset, so two faces proposing it still propose one point.
constexpr double kLatticeJitter = 1e-4;
Vec3 jittered(const Vec3& node, double a) {
    std::uint64_t h = 0x9e3779b97f4a7c15u;
    for (double c : {node.x, node.y, node.z}) {
        h ^= static_cast<std::uint64_t>(std::llround(2 * c / a)) + 0x9e3779b97f4a7c15u + (h << 6) + (h >> 2);
        h *= 0xbf58476d1ce4e5b9u;
        h ^= h >> 31;
    }
    const auto offset = [&](int shift) { return a * kLatticeJitter * (double((h >> shift) & 0xFFFFF) / 0x100000 - 0.5); };
    return {node.x + offset(0), node.y + offset(21), node.z + offset(42)};
}

}  // namespace

std::vector<double> far_lattice_points(const double* lo, const double* hi, const ControlSpace& space,
                                       const FarLattice& lattice, double max_nodes) {
    std::vector<double> out;
    const double far = space.far_size();
    if (!(lattice.spacing > 0) || !(far > 0)) return out;
    const double a = lattice.spacing * far;
    // Corners a*i and centres a*(i + 0.5) per axis, computed as nearest_bcc_node does, so that a
    // node a face proposes later is this very point. The nodes are only counted here and made
    // where they are tested; the indices must stay exact integers, and the count within
    // max_nodes, before any is made.
    struct Grid {
        double shift;
        std::int64_t first[3], count[3];
        std::size_t size() const { return std::size_t(count[0]) * std::size_t(count[1]) * std::size_t(count[2]); }
    };
    Grid grid[2] = {{0.0, {}, {}}, {0.5, {}, {}}};
    double total_nodes = 0;
    for (Grid& g : grid) {
        double nodes = 1;
        for (int d = 0; d < 3; ++d) {
            if (!(std::abs(lo[d] / a) < 0x1p50 && std::abs(hi[d] / a) < 0x1p50)) return out;
            const double first = std::ceil(lo[d] / a - g.shift), count = std::max(0.0, std::floor(hi[d] / a - g.shift) - first + 1);
            g.first[d] = static_cast<std::int64_t>(first);
            g.count[d] = static_cast<std::int64_t>(count);
            nodes *= count;
        }
        total_nodes += nodes;
    }
    if (!(total_nodes <= max_nodes)) return out;
    const auto node = [&](std::size_t n) {
        const Grid& g = n < grid[0].size() ? grid[0] : grid[1];
        if (n >= grid[0].size()) n -= grid[0].size();
        const std::size_t i = n % std::size_t(g.count[0]), j = n / std::size_t(g.count[0]) % std::size_t(g.count[1]),
                          k = n / std::size_t(g.count[0]) / std::size_t(g.count[1]);
        return Vec3{a * (double(g.first[0] + std::int64_t(i)) + g.shift), a * (double(g.first[1] + std::int64_t(j)) + g.shift),
                    a * (double(g.first[2] + std::int64_t(k)) + g.shift)};
    };
    const std::size_t total = grid[0].size() + grid[1].size();
    std::vector<std::uint8_t> keep(total, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, 256), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t n = r.begin(); n < r.end(); ++n) {
            const Vec3 v = node(n);
            const double q[3] = {v.x, v.y, v.z};
            keep[n] = space.far_and_clear(q, lattice.clearance * far) ? 1 : 0;
        }
    });
    for (std::size_t n = 0; n < total; ++n)
        if (keep[n]) {
            const Vec3 p = jittered(node(n), a);
            out.insert(out.end(), {p.x, p.y, p.z});
        }
    return out;
}

CarriedSize carried_size(const MeshView& m, const index_t* v, const double* p, const ControlSpace& space) {
    CarriedSize best{space.far_size(), kNoIndex};
    for (int k = 0; k < 4; ++k) {
        const index_t i = m.source[v[k]];
        if (i == kNoIndex || i == best.source) continue;
        const double h = space.term(i, p);
        if (h < best.h || (h == best.h && i < best.source)) best = {h, i};
    }
    return best;
}

std::vector<double> point_sizes(std::span<const double> xyz, const ControlSpace& space) {
    std::vector<double> h(xyz.size() / 3);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, h.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) h[i] = space.size(xyz.data() + 3 * i);
    });
    return h;
}

std::vector<index_t> point_sources(std::span<const double> xyz, const ControlSpace& space) {
    std::vector<index_t> source(xyz.size() / 3);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, source.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) source[i] = space.source(xyz.data() + 3 * i);
    });
    return source;
}

bool tet_too_big(const MeshView& m, index_t tet, double tolerance) {
    const index_t* v = m.tets.vertex(tet);
    const Vec3 p[4] = {at(m, v[0]), at(m, v[1]), at(m, v[2]), at(m, v[3])};
    double sum = 0;
    for (int e = 0; e < 6; ++e) sum += norm(p[kTetTopology.edge[e].a] - p[kTetTopology.edge[e].b]);
    const double h = 0.25 * (m.h[v[0]] + m.h[v[1]] + m.h[v[2]] + m.h[v[3]]);
    return sum / 6.0 > tolerance * h;
}

std::vector<index_t> active_faces(const MeshView& m, double tolerance) {
    TooBigMemo memo;
    return active_faces(m, tolerance, memo);
}

std::vector<index_t> active_faces(const MeshView& m, double tolerance, TooBigMemo& memo) {
    const index_t n = m.tets.size();
    const index_t known_slots = static_cast<index_t>(std::min<std::size_t>(memo.big.size(), n));
    const index_t known_points = memo.points;
    memo.big.resize(n, 0);
    std::atomic<std::uint64_t> tests{0};
    tbb::parallel_for(tbb::blocked_range<index_t>(0, n, 1024), [&](const tbb::blocked_range<index_t>& r) {
        std::uint64_t made = 0;
        for (index_t t = r.begin(); t < r.end(); ++t) {
            const index_t* v = m.tets.vertex(t);
            if (v[0] == kFreeSlot) {
                memo.big[t] = 0;
            } else if (t >= known_slots || std::max({v[0], v[1], v[2], v[3]}) >= known_points) {
                memo.big[t] = tet_too_big(m, t, tolerance) ? 1 : 0;
                ++made;
            }
        }
        tests.fetch_add(made, std::memory_order_relaxed);
    });
    memo.tests += tests.load();
    memo.points = static_cast<index_t>(m.xyz.size() / 3);
    const std::vector<std::uint8_t>& big = memo.big;
    // Each fixed chunk of slots lists its faces; joined in chunk order they stay increasing.
    constexpr index_t kChunk = 16384;
    const index_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<std::vector<index_t>> listed(chunks);
    tbb::parallel_for(index_t{0}, chunks, [&](index_t c) {
        for (index_t t = c * kChunk; t < std::min(n, (c + 1) * kChunk); ++t) {
            if (!big[t]) continue;
            for (unsigned f = 0; f < 4; ++f) {
                const index_t code = m.tets.neighbour(4 * t + f);
                if (code == kNoAdjacent || !big[code >> 2]) listed[c].push_back(4 * t + f);
            }
        }
    });
    std::vector<index_t> faces;
    for (const auto& l : listed) faces.insert(faces.end(), l.begin(), l.end());
    return faces;
}

std::vector<Candidate> propose_points(const MeshView& m, std::span<const index_t> faces, const ControlSpace& space,
                                      const FarLattice& lattice) {
    ProposalMemo memo;
    return propose_points(m, faces, space, memo, lattice);
}

std::vector<Candidate> propose_points(const MeshView& m, std::span<const index_t> faces, const ControlSpace& space,
                                      ProposalMemo& memo, const FarLattice& lattice) {
    constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    // Each array lives only as long as it is needed: in the first rounds, with tens of
    // thousands of active faces, these arrays set the refinement's memory peak.
    std::vector<ProposalMemo::Entry> before;
    before.swap(memo.entries);
    // Filled in the parallel loops below: no serial zeroing.
    UninitVector<ProposalMemo::Entry> now(faces.size());
    std::vector<std::uint8_t> known(faces.size(), 0);
    const double far = space.far_size();
    // Ideal points that snap to a lattice node if the node passes far_and_clear: the node, and
    // the faces' positions in `faces`. Several faces of a round propose the same node, and the
    // answer depends on the node only, so each distinct node is asked once (below).
    UninitVector<Vec3> node_of(faces.size());  // set where at_node
    std::vector<std::uint8_t> at_node(faces.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
        std::uint64_t reused = 0;
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
            const index_t t = faces[i] >> 2, f = faces[i] & 3;
            const index_t* v = m.tets.vertex(t);
            ProposalMemo::Entry& e = now[i];
            e.face = faces[i];
            std::copy_n(v, 4, e.ids.begin());
            const auto hit = std::lower_bound(before.begin(), before.end(), faces[i],
                                              [](const ProposalMemo::Entry& x, index_t code) { return x.face < code; });
            if (hit != before.end() && hit->face == faces[i] && hit->ids == e.ids) {
                e = *hit;
                ++reused;
            } else {
                const auto& node = kTetTopology.face[f].node;
                const Vec3 a = at(m, v[node[0]]), b = at(m, v[node[1]]), c = at(m, v[node[2]]);
                const Vec3 g = (1.0 / 3.0) * (a + b + c);
                const Vec3 outward = cross(b - a, c - a);  // out of t
                const double len = norm(outward);
                if (!(len > 0)) continue;
                const double rho2 = (distance2(g, a) + distance2(g, b) + distance2(g, c)) / 3.0;
                // Apex at distance h from the face's vertices when the face allows it.
                const auto apex = [&](double h) {
                    return g - (std::sqrt(std::max(h * h - rho2, 0.25 * h * h)) / len) * outward;
                };
                // h where the new tet will be (halfway to the apex), not at the face: in a graded
                // field the face's own size is too small for the tet it starts (a higher mean
                // collapse in fewer rounds: bench/results/tuning-notes.md).
                const double h_face = (m.h[v[node[0]]] + m.h[v[node[1]]] + m.h[v[node[2]]]) / 3.0;
                const Vec3 first = apex(h_face);
                const Vec3 mid = 0.5 * (g + first);
                const double mq[3] = {mid.x, mid.y, mid.z};
                const double h_mid = carried_size(m, v, mq, space).h;
                Vec3 p = apex(h_mid);
                e.h = kUnknown;
                // Snap only where h is the far size (the lattice's spacing is right there) and the
                // front is far enough for advancing-front layers to fill the seam between them.
                // The test at the node needs a query of the front's nodes: only ideal points
                // already at the far size ask it.
                if (lattice.spacing > 0 && h_mid >= far) {
                    node_of[i] = nearest_bcc_node(p, lattice.spacing * far);
                    at_node[i] = 1;
                }
                e.p[0] = p.x;
                e.p[1] = p.y;
                e.p[2] = p.z;
            }
            known[i] = 1;
        }
        memo.reused_total.fetch_add(reused, std::memory_order_relaxed);
    });
    before = {};
    std::vector<index_t> asking = kept_indices(faces.size(), [&](std::size_t i) { return at_node[i] != 0; });
    const auto node_less = [&](index_t i, index_t j) {
        const Vec3 &a = node_of[i], &b = node_of[j];
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    // By node, then position: one order, whatever sorts it.
    tbb::parallel_sort(asking.begin(), asking.end(),
                       [&](index_t i, index_t j) { return node_less(i, j) || (!node_less(j, i) && i < j); });
    // Runs of equal nodes in `asking`.
    std::vector<index_t> run_begin =
        kept_indices(asking.size(), [&](std::size_t k) { return k == 0 || node_less(asking[k - 1], asking[k]); });
    run_begin.push_back(static_cast<index_t>(asking.size()));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, run_begin.size() - 1, 64), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
            const Vec3 node = node_of[asking[run_begin[k]]];
            const double nq[3] = {node.x, node.y, node.z};
            if (!space.far_and_clear(nq, lattice.clearance * far)) continue;
            const Vec3 p = jittered(node, lattice.spacing * far);
            for (std::size_t j = run_begin[k]; j < run_begin[k + 1]; ++j) {
                ProposalMemo::Entry& e = now[asking[j]];
                e.p[0] = p.x;
                e.p[1] = p.y;
                e.p[2] = p.z;
                e.h = far;
            }
        }
    });
    node_of = {};
    at_node = {};
    asking = {};
    run_begin = {};
    // Filled where ok (a slot only where ok): no serial zeroing.
    UninitVector<Candidate> out(faces.size());
    std::vector<std::uint8_t> ok(faces.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
            if (!known[i]) continue;
            const ProposalMemo::Entry& e = now[i];
            const index_t holder = walk_to(m, faces[i] >> 2, e.p, static_cast<std::uint32_t>(faces[i]) * 2654435761u | 1u);
            if (holder == kNoIndex) continue;
            // h at the point from the corners of the tet that holds it, its nearest mesh points.
            const CarriedSize h = std::isnan(e.h) ? carried_size(m, m.tets.vertex(holder), e.p, space)
                                                  : CarriedSize{e.h, kNoIndex};
            out[i] = {{e.p[0], e.p[1], e.p[2]}, h.h, holder, h.source};
            ok[i] = 1;
        }
    });
    // Faces come in increasing order, so the entries stay sorted for the next round's search.
    memo.entries = kept_items(now, [&](std::size_t i) { return known[i] != 0; });
    now = {};
    return kept_items(out, [&](std::size_t i) { return ok[i] != 0; });
}

namespace {

// A set of points (GrowingPoints' kept ones), in two k-d trees split at the median of the
// bounding box's longest axis: the two halves build at the same time (nanoflann builds
// serially, and one tree over all of them was the longest serial step of a round, serpentine
// lift: 0.3 s over the rounds). A query whose ball reaches across the plane asks both, so
// `empty_within` answers exactly as one tree would.
class SplitPoints {
public:
    explicit SplitPoints(std::span<const double> xyz) : size_(xyz.size() / 3) {
        std::vector<index_t> order(size_);
        std::iota(order.begin(), order.end(), index_t{0});
        double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
        for (std::size_t i = 0; i < size_; ++i)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], xyz[3 * i + a]);
                hi[a] = std::max(hi[a], xyz[3 * i + a]);
            }
        for (int a = 1; a < 3; ++a)
            if (hi[a] - lo[a] > hi[axis_] - lo[axis_]) axis_ = a;
        const std::size_t half = size_ / 2;
        const auto coordinate = [&](index_t i) { return xyz[3 * std::size_t{i} + axis_]; };
        if (size_ > 0) {
            std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(half), order.end(),
                             [&](index_t i, index_t j) { return coordinate(i) < coordinate(j); });
            split_ = coordinate(order[half]);  // the low half is <= split_, the high half >= split_
        }
        for (int side = 0; side < 2; ++side) {
            Half& h = half_[side];
            const std::size_t from = side == 0 ? 0 : half, to = side == 0 ? half : size_;
            for (std::size_t k = from; k < to; ++k) {
                const std::size_t i = order[k];
                h.x.push_back(xyz[3 * i]);
                h.y.push_back(xyz[3 * i + 1]);
                h.z.push_back(xyz[3 * i + 2]);
            }
        }
    }
    // The trees, one task each (beside whatever else the caller runs at the same time).
    void build_low() { half_[0].build(); }
    void build_high() { half_[1].build(); }

    // No point strictly closer than `radius` to q (PointIndex::within's test).
    bool empty_within(const Vec3& q, double radius) const {
        const double x = axis_ == 0 ? q.x : axis_ == 1 ? q.y : q.z;
        const int side = x < split_ ? 0 : 1;
        if (!half_[side].empty_within(q, radius)) return false;
        // A point of the other half is at least |x - split| away along the axis.
        const double gap = side == 0 ? split_ - x : x - split_;
        return gap >= radius || half_[1 - side].empty_within(q, radius);
    }

private:
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    struct Half {
        std::vector<double> x, y, z;
        std::optional<PointIndex> tree;
        void build() {
            if (!x.empty()) tree.emplace(x, y, z);
        }
        bool empty_within(const Vec3& q, double radius) const { return !tree || !tree->any_within(q, radius); }
    };
    std::size_t size_;
    int axis_ = 0;
    double split_ = 0;
    Half half_[2];
};

}  // namespace

struct GrowingPoints::Impl {
    std::vector<double> all;           // every point, 3 coordinates each
    std::size_t indexed = 0;           // points [0, indexed) are in `kept`
    std::unique_ptr<SplitPoints> kept;
    std::vector<double> x, y, z;       // points [indexed, in_recent)
    std::size_t in_recent = 0;
    std::optional<PointIndex> recent;

    // Builds the trees the points appended since the last call need, `beside` at the same time.
    template <class F>
    void prepare(F&& beside) {
        const std::size_t n = all.size() / 3;
        if (!kept || 4 * (n - indexed) > indexed) {
            kept = std::make_unique<SplitPoints>(all);
            indexed = in_recent = n;
            recent.reset();
            x.clear();
            y.clear();
            z.clear();
            tbb::parallel_invoke([&] { kept->build_low(); }, [&] { kept->build_high(); }, beside);
            return;
        }
        if (in_recent == n) {
            beside();
            return;
        }
        recent.reset();  // it refers to x, y, z, which grow now
        for (std::size_t i = in_recent; i < n; ++i) {
            x.push_back(all[3 * i]);
            y.push_back(all[3 * i + 1]);
            z.push_back(all[3 * i + 2]);
        }
        in_recent = n;
        tbb::parallel_invoke([&] { recent.emplace(x, y, z); }, beside);
    }
    bool empty_within(const Vec3& q, double radius) const {
        return kept->empty_within(q, radius) && !(recent && recent->any_within(q, radius));
    }
};

GrowingPoints::GrowingPoints(std::span<const double> xyz) : impl_(std::make_unique<Impl>()) {
    impl_->all.assign(xyz.begin(), xyz.end());
}
GrowingPoints::~GrowingPoints() = default;
void GrowingPoints::append(std::span<const double> xyz) { impl_->all.insert(impl_->all.end(), xyz.begin(), xyz.end()); }
std::size_t GrowingPoints::size() const { return impl_->all.size() / 3; }

std::vector<index_t> select_points(std::span<const Candidate> c, std::span<const double> existing, double factor,
                                   const MeshView* mesh) {
    GrowingPoints points(existing);
    return select_points(c, points, factor, mesh);
}

namespace {

// A corner of the candidate's holding tet within its radius, by a margin that the trees'
// rounding of the same squared distance cannot cross.
bool corner_within(const MeshView& m, const Candidate& c, double radius) {
    const double limit = radius * radius * (1 - 1e-9);
    const index_t* v = m.tets.vertex(c.tet);
    for (int k = 0; k < 4; ++k) {
        const double* q = ptr(m, v[k]);
        const double dx = c.p[0] - q[0], dy = c.p[1] - q[1], dz = c.p[2] - q[2];
        if (dx * dx + dy * dy + dz * dz < limit) return true;
    }
    return false;
}

}  // namespace

std::vector<index_t> select_points(std::span<const Candidate> c, GrowingPoints& existing, double factor,
                                   const MeshView* mesh) {
    const std::size_t n = c.size();
    const auto place = [&](std::size_t i) { return Vec3{c[i].p[0], c[i].p[1], c[i].p[2]}; };
    std::vector<index_t> kept;
    if (!n) return kept;
    GrowingPoints::Impl& points = *existing.impl_;
    points.prepare([] {});
    // Far enough from existing points: independent per candidate, parallel.
    std::vector<std::uint8_t> free_of_points(n, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
            if (mesh && corner_within(*mesh, c[i], factor * c[i].h)) continue;
            free_of_points[i] = points.empty_within(place(i), factor * c[i].h) ? 1 : 0;
        }
    });
    // Among candidates: greedy in order, so earlier ones win whatever the thread count. Only the
    // candidates that passed the first test can take a place or block a later one, so the tree
    // holds those alone (after the first rounds most candidates fall at the first test). The
    // queries are independent, so they run in parallel; only the greedy pass is serial.
    const std::vector<index_t> free = kept_indices(n, [&](std::size_t i) { return free_of_points[i] != 0; });
    if (free.empty()) return kept;
    std::vector<double> fx(free.size()), fy(free.size()), fz(free.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, free.size(), 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
            fx[k] = c[free[k]].p[0];
            fy[k] = c[free[k]].p[1];
            fz[k] = c[free[k]].p[2];
        }
    });
    const PointIndex cands(fx, fy, fz);
    // earlier[k]: the positions in `free` of the free candidates before free[k] within its radius.
    std::vector<std::vector<index_t>> earlier(free.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, free.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
        // Only whether an earlier neighbour is taken matters, not their order: no sort.
        std::vector<std::pair<index_t, double>> near;
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
            const index_t i = free[k];
            cands.within_unordered(place(i), factor * c[i].h, near);
            for (const auto& hit : near)
                if (hit.first < k) earlier[k].push_back(hit.first);
        }
    });
    std::vector<std::uint8_t> taken(free.size(), 0);
    for (std::size_t k = 0; k < free.size(); ++k) {
        if (std::any_of(earlier[k].begin(), earlier[k].end(), [&](index_t j) { return taken[j] != 0; })) continue;
        taken[k] = 1;
        kept.push_back(free[k]);
    }
    return kept;
}

}  // namespace tubemesh::tets
