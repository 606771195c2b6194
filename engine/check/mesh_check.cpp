#include "engine/check/mesh_check.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "engine/core/vec3_ops.hpp"

// How the check works. Every cell face becomes a record: its node ids sorted (the key), the
// face's slot (which cell and local face, see FaceSlots) and its form (how the face's cycle runs
// through the sorted nodes: orientation, and for a quad which node is opposite the smallest).
// Sorting the records (a counting sort on the smallest node, then small sorts) puts the views of
// one face next to each other, so matching is a scan over runs of equal keys; triangles and quads
// are kept in two arrays. Free faces are then matched
// against the quads' corner triangles (a quad facing triangles), their edges are sorted the same
// way (watertightness), and the stored boundary faces are looked up by binary search.
// Sums of doubles are taken over fixed blocks in a fixed order, and offending elements are sorted
// before they are reported, so nothing depends on the thread count.

namespace tubemesh {

namespace {

constexpr int kViolationKindCount = 7;
static_assert(static_cast<int>(ViolationKind::BoundaryFaceNotOnCell) == kViolationKindCount - 1);
// Cells are named by casting their CellKind to an ElementRef::Set.
static_assert(static_cast<int>(ElementRef::Set::Tet) == static_cast<int>(CellKind::Tet) &&
              static_cast<int>(ElementRef::Set::Pyramid) == static_cast<int>(CellKind::Pyramid) &&
              static_cast<int>(ElementRef::Set::Hex) == static_cast<int>(CellKind::Hex));
constexpr std::size_t kFirstCount = 10;
constexpr index_t kSumBlock = 4096;  // cells per partial sum: fixed, so sums do not depend on threads

// ---------------------------------------------------------------------------------------------
// Corner frames, derived from the topology tables so they cannot disagree with the faces.

// At a corner with three edges, det3(p[a] - p[node], p[b] - p[node], p[c] - p[node]) > 0 for a
// valid cell: the hex corner Jacobian, the pyramid base-corner tet, the tet's signed volume.
struct CornerFrame {
    std::uint8_t node, a, b, c;
};

struct CornerFrames {
    std::array<CornerFrame, 8> frame{};
    int count = 0;
};

// Around a corner v of an outward face, ..., prev, v, next, ... has the face normal
// (next - v) x (prev - v) pointing out of the cell, so (prev, next, third edge) is right-handed.
constexpr CornerFrames corner_frames(const CellTopology& t) {
    CornerFrames out{};
    for (int v = 0; v < t.node_count; ++v) {
        int degree = 0;
        std::array<int, 4> nbr{};
        for (int e = 0; e < t.edge_count; ++e) {
            if (t.edge[e].a == v && degree < 4) nbr[degree++] = t.edge[e].b;
            if (t.edge[e].b == v && degree < 4) nbr[degree++] = t.edge[e].a;
        }
        if (degree != 3) continue;  // the pyramid apex: its tets are the base corners' tets
        for (int f = 0; f < t.face_count; ++f) {
            const LocalFace& face = t.face[f];
            int k = 0;
            while (k < face.size && face.node[k] != v) ++k;
            if (k == face.size) continue;
            const int prev = face.node[(k + face.size - 1) % face.size];
            const int next = face.node[(k + 1) % face.size];
            int third = 0;
            for (int i = 0; i < 3; ++i)
                if (nbr[i] != prev && nbr[i] != next) third = nbr[i];
            out.frame[out.count++] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(prev),
                                      static_cast<std::uint8_t>(next), static_cast<std::uint8_t>(third)};
            break;
        }
    }
    return out;
}

constexpr std::array<CornerFrames, kCellKindCount> kCornerFrames = {
    corner_frames(kTetTopology), corner_frames(kPyramidTopology), corner_frames(kHexTopology)};

// A tet's four corner determinants are one number in exact arithmetic; computing only the first
// keeps "valid" equal to "positive signed volume" even for nearly flat tets.
constexpr int checked_corner_count(CellKind k) { return k == CellKind::Tet ? 1 : kCornerFrames[int(k)].count; }

// ---------------------------------------------------------------------------------------------
// Cell measures.

using CellPoints = std::array<Vec3, 8>;

CellPoints gather(const HybridMesh& m, std::span<const index_t> nodes) {
    CellPoints p{};
    for (std::size_t k = 0; k < nodes.size(); ++k) p[k] = m.point(nodes[k]);
    return p;
}

// At most 8 nodes: pairwise comparison beats sorting a copy.
bool repeats_a_node(std::span<const index_t> nodes) {
    for (std::size_t i = 1; i < nodes.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (nodes[i] == nodes[j]) return true;
    return false;
}

bool has_positive_corners(CellKind kind, const CellPoints& p) {
    const CornerFrames& frames = kCornerFrames[static_cast<int>(kind)];
    for (int i = 0; i < checked_corner_count(kind); ++i) {
        const CornerFrame& f = frames.frame[i];
        const Vec3 o = p[f.node];
        if (!(det3(p[f.a] - o, p[f.b] - o, p[f.c] - o) > 0)) return false;  // NaN is not positive either
    }
    return true;
}

// Six times the volume of the cone from c over an outward face. For a quad, the cone over its
// bilinear patch x(u, v): volume = 1/3 of the integral of (x - c).(x_u x x_v) over the unit
// square. That integrand is bilinear in (u, v) (its u^2 and v^2 terms vanish), so the integral is
// the mean of its four corner values, which are the corner determinants below:
// six times the volume = 2 * mean = sum / 2, i.e. the mean of the two diagonal splits.
double six_cone_volume(const CellPoints& p, const LocalFace& face, Vec3 c) {
    if (face.size == 3) return det3(p[face.node[0]] - c, p[face.node[1]] - c, p[face.node[2]] - c);
    double sum = 0;
    for (int k = 0; k < 4; ++k)
        sum += det3(p[face.node[(k + 3) % 4]] - c, p[face.node[k]] - c, p[face.node[(k + 1) % 4]] - c);
    return sum / 2;
}

// Volume bounded by the cell's faces, quads taken bilinear (see the header).
double cell_volume(CellKind kind, const CellPoints& p) {
    const CellTopology& t = topology(kind);
    if (kind == CellKind::Tet) return det3(p[1] - p[0], p[2] - p[0], p[3] - p[0]) / 6;
    Vec3 c{0, 0, 0};
    for (int k = 0; k < t.node_count; ++k) c = {c.x + p[k].x, c.y + p[k].y, c.z + p[k].z};
    c = {c.x / t.node_count, c.y / t.node_count, c.z / t.node_count};
    double six_v = 0;
    for (int f = 0; f < t.face_count; ++f) six_v += six_cone_volume(p, t.face[f], c);
    return six_v / 6;
}

double triangle_area(Vec3 a, Vec3 b, Vec3 c) { return norm(cross(b - a, c - a)) / 2; }

// ---------------------------------------------------------------------------------------------
// Offending elements, collected per thread and sorted before they are reported.

std::uint64_t ref_code(ElementRef::Set set, index_t index) {
    return (std::uint64_t{static_cast<unsigned>(set)} << 32) | index;
}

ElementRef ref_from_code(std::uint64_t code) {
    return {static_cast<ElementRef::Set>(code >> 32), static_cast<index_t>(code & 0xffffffffu)};
}

class ViolationSink {
public:
    void add(ViolationKind kind, ElementRef::Set set, index_t index) {
        lists_.local()[static_cast<int>(kind)].push_back(ref_code(set, index));
    }

    std::vector<Violation> collect() {
        std::vector<Violation> out;
        for (int k = 0; k < kViolationKindCount; ++k) {
            std::vector<std::uint64_t> all;
            for (const Lists& l : lists_) all.insert(all.end(), l[k].begin(), l[k].end());
            if (all.empty()) continue;
            tbb::parallel_sort(all.begin(), all.end());
            all.erase(std::unique(all.begin(), all.end()), all.end());
            Violation v{static_cast<ViolationKind>(k), static_cast<index_t>(all.size()), {}};
            for (std::size_t i = 0; i < std::min(all.size(), kFirstCount); ++i)
                v.first.push_back(ref_from_code(all[i]));
            out.push_back(std::move(v));
        }
        return out;
    }

private:
    using Lists = std::array<std::vector<std::uint64_t>, kViolationKindCount>;
    tbb::enumerable_thread_specific<Lists> lists_;
};

// Sum of term(i) for i < n over fixed blocks added in block order: the same bits for any
// number of threads. term may also report violations.
template <class Term>
double block_sum(index_t n, Term term) {
    const index_t blocks = (n + kSumBlock - 1) / kSumBlock;
    std::vector<double> partial(blocks, 0.0);
    tbb::parallel_for(index_t{0}, blocks, [&](index_t b) {
        double s = 0;
        const auto end = static_cast<index_t>(std::min<std::uint64_t>(n, std::uint64_t{b + 1} * kSumBlock));
        for (index_t i = b * kSumBlock; i < end; ++i) s += term(i);
        partial[b] = s;
    });
    return std::accumulate(partial.begin(), partial.end(), 0.0);
}

// Degenerate and inverted cells; returns the summed volume of all cells.
double check_cells(const HybridMesh& mesh, ViolationSink& sink) {
    double volume = 0;
    for (CellKind kind : kAllCellKinds) {
        const auto set = static_cast<ElementRef::Set>(kind);
        volume += block_sum(mesh.cell_count(kind), [&](index_t i) {
            const std::span<const index_t> nodes = mesh.cell(kind, i);
            const CellPoints p = gather(mesh, nodes);
            if (repeats_a_node(nodes))
                sink.add(ViolationKind::DegenerateCell, set, i);
            else if (!has_positive_corners(kind, p))
                sink.add(ViolationKind::NonPositiveVolume, set, i);
            return cell_volume(kind, p);
        });
    }
    return volume;
}

// ---------------------------------------------------------------------------------------------
// Face records.

enum class Shape { Tri = 0, Quad = 1 };
constexpr Shape shape_of(const LocalFace& f) { return f.size == 3 ? Shape::Tri : Shape::Quad; }

// Bits of a record's code below the form; the form sits above them.
constexpr int slot_bits(Shape s) { return s == Shape::Tri ? 31 : 29; }

// Where a cell kind's faces of one shape sit among that shape's slots.
struct ShapeFaces {
    int per_cell = 0;                     // faces of this shape per cell
    std::array<std::uint8_t, 6> local{};  // local face of the r-th face of this shape
};

constexpr ShapeFaces shape_faces(const CellTopology& t, Shape s) {
    ShapeFaces out{};
    for (int f = 0; f < t.face_count; ++f)
        if (shape_of(t.face[f]) == s) out.local[out.per_cell++] = static_cast<std::uint8_t>(f);
    return out;
}

constexpr std::array<std::array<ShapeFaces, 2>, kCellKindCount> kShapeFaces = {
    {{shape_faces(kTetTopology, Shape::Tri), shape_faces(kTetTopology, Shape::Quad)},
     {shape_faces(kPyramidTopology, Shape::Tri), shape_faces(kPyramidTopology, Shape::Quad)},
     {shape_faces(kHexTopology, Shape::Tri), shape_faces(kHexTopology, Shape::Quad)}}};

// Every cell face of one shape has a slot: numbered kind by kind, cell by cell, in local face
// order. A slot names its cell with a division, no lookup table.
class FaceSlots {
public:
    FaceSlots(const HybridMesh& mesh, Shape shape) : shape_(shape) {
        std::uint64_t next = 0;
        for (CellKind k : kAllCellKinds) {
            base_[static_cast<int>(k)] = next;
            next += std::uint64_t{mesh.cell_count(k)} * faces(k).per_cell;
        }
        total_ = next;
        if (total_ >= (std::uint64_t{1} << slot_bits(shape)))
            throw Error("check_mesh: " + std::to_string(total_) +
                        (shape == Shape::Tri ? " triangular" : " quadrilateral") +
                        " cell faces are more than the check can index; check the mesh in parts");
    }

    const ShapeFaces& faces(CellKind k) const { return kShapeFaces[static_cast<int>(k)][static_cast<int>(shape_)]; }
    std::uint64_t total() const { return total_; }
    index_t slot(CellKind k, index_t cell, int rank) const {
        return static_cast<index_t>(base_[static_cast<int>(k)] + std::uint64_t{cell} * faces(k).per_cell + rank);
    }
    ElementRef cell_of(index_t slot) const {
        int k = kCellKindCount - 1;
        while (faces(static_cast<CellKind>(k)).per_cell == 0 || slot < base_[k]) --k;
        const auto per = static_cast<std::uint64_t>(faces(static_cast<CellKind>(k)).per_cell);
        return {static_cast<ElementRef::Set>(k), static_cast<index_t>((slot - base_[k]) / per)};
    }

private:
    Shape shape_;
    std::array<std::uint64_t, kCellKindCount> base_{};
    std::uint64_t total_ = 0;
};

// One view of a face: sorted node ids, then the code (form above slot_bits, slot below).
// The form's bit 0 is the orientation (1 when the cycle is an odd permutation of the key for a
// triangle; for a quad, when the smallest node's successor is larger than its predecessor);
// bits 1-2 of a quad's form give the key position of the node opposite the smallest. Two views
// of one face match when form >> 1 agrees, and face each other when bit 0 differs.
template <int N>
struct FaceRecord {
    std::array<index_t, N> key;
    index_t code;

    bool operator<(const FaceRecord& o) const {
        for (int i = 0; i < N; ++i)
            if (key[i] != o.key[i]) return key[i] < o.key[i];
        return code < o.code;
    }
};

using TriRecord = FaceRecord<3>;
using QuadRecord = FaceRecord<4>;

template <int N>
constexpr Shape shape_for() {
    return N == 3 ? Shape::Tri : Shape::Quad;
}

template <int N>
index_t form_of(const FaceRecord<N>& r) {
    return r.code >> slot_bits(shape_for<N>());
}

template <int N>
index_t slot_of(const FaceRecord<N>& r) {
    return r.code & ((index_t{1} << slot_bits(shape_for<N>())) - 1);
}

// The record of a face given as its cycle of nodes (outward for cell faces).
template <int N>
FaceRecord<N> make_record(const std::array<index_t, N>& cycle, index_t slot) {
    const int m = static_cast<int>(std::min_element(cycle.begin(), cycle.end()) - cycle.begin());
    const index_t succ = cycle[(m + 1) % N], pred = cycle[(m + N - 1) % N];
    FaceRecord<N> r{cycle, 0};
    // Sorted by compare-exchange: std::sort's call for three or four ids cost more than the rest
    // of the check's face records together.
    const auto order = [&r](int i, int j) {
        if (r.key[j] < r.key[i]) std::swap(r.key[i], r.key[j]);
    };
    if constexpr (N == 3) {
        r.key = {cycle[m], std::min(succ, pred), std::max(succ, pred)};
    } else {
        order(0, 1);
        order(2, 3);
        order(0, 2);
        order(1, 3);
        order(1, 2);
    }
    index_t form = succ > pred ? 1 : 0;
    if constexpr (N == 4) {
        const index_t opposite = cycle[(m + 2) % 4];
        form |= static_cast<index_t>(std::find(r.key.begin(), r.key.end(), opposite) - r.key.begin()) << 1;
    }
    r.code = (form << slot_bits(shape_for<N>())) | slot;
    return r;
}

template <int N>
bool same_key(const FaceRecord<N>& a, const FaceRecord<N>& b) {
    return a.key == b.key;
}

template <int N>
bool key_less(const FaceRecord<N>& a, const FaceRecord<N>& b) {
    return a.key < b.key;
}

// Calls fn(cycle, slot) for every face of one shape of every cell that repeats no node.
template <int N, class Fn>
void for_each_cell_face(const HybridMesh& mesh, const FaceSlots& slots, Fn fn) {
    for (CellKind kind : kAllCellKinds) {
        const ShapeFaces& sf = slots.faces(kind);
        if (sf.per_cell == 0) continue;
        tbb::parallel_for(tbb::blocked_range<index_t>(0, mesh.cell_count(kind)), [&](const auto& range) {
            for (index_t i = range.begin(); i != range.end(); ++i) {
                const std::span<const index_t> nodes = mesh.cell(kind, i);
                if (repeats_a_node(nodes)) continue;
                for (int r = 0; r < sf.per_cell; ++r) {
                    const LocalFace& face = topology(kind).face[sf.local[r]];
                    std::array<index_t, N> cycle{};
                    for (int k = 0; k < N; ++k) cycle[k] = nodes[face.node[k]];
                    fn(cycle, slots.slot(kind, i, r));
                }
            }
        });
    }
}

template <int N>
index_t smallest(const std::array<index_t, N>& cycle) {
    return *std::min_element(cycle.begin(), cycle.end());
}

// All cell faces of one shape in (key, code) order; faces of cells that repeat a node are left
// out. A counting sort on the smallest node puts each face in a bucket of a few dozen, which are
// then sorted one by one: several times faster than sorting the whole array, and since
// (key, code) is a total order the result does not depend on the order of the scatter.
template <int N>
std::vector<FaceRecord<N>> build_records(const HybridMesh& mesh, const FaceSlots& slots, const Pulse& pulse) {
    const index_t points = mesh.point_count();
    std::vector<std::atomic<index_t>> cursor(points);
    for_each_cell_face<N>(mesh, slots, [&](const std::array<index_t, N>& cycle, index_t) {
        cursor[smallest<N>(cycle)].fetch_add(1, std::memory_order_relaxed);
    });
    beat(pulse);
    std::vector<index_t> first(std::size_t{points} + 1, 0);  // bucket v: [first[v], first[v + 1])
    for (index_t v = 0; v < points; ++v) {
        first[v + 1] = first[v] + cursor[v].load(std::memory_order_relaxed);
        cursor[v].store(first[v], std::memory_order_relaxed);
    }
    std::vector<FaceRecord<N>> recs(first[points]);
    for_each_cell_face<N>(mesh, slots, [&](const std::array<index_t, N>& cycle, index_t slot) {
        recs[cursor[smallest<N>(cycle)].fetch_add(1, std::memory_order_relaxed)] = make_record<N>(cycle, slot);
    });
    beat(pulse);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, points), [&](const auto& range) {
        for (index_t v = range.begin(); v != range.end(); ++v)
            std::sort(recs.begin() + first[v], recs.begin() + first[v + 1]);
    });
    return recs;
}

// ---------------------------------------------------------------------------------------------
// Matching the views of each face.

enum class FaceState : std::uint8_t {
    Free,         // on one cell: a boundary face unless it faces part of a quad
    Interior,     // on two cells
    Overshared,   // on three or more cells
    NonMatching,  // free, but a triangle covering part of a free quad (or that quad)
};

// Runs fn(first, last) for every run of records with equal keys, in parallel; a run that starts
// in a chunk is handled by that chunk even when it ends beyond it. Beats `pulse` once a chunk.
template <class Rec, class Fn>
void for_each_run(const std::vector<Rec>& recs, const Pulse& pulse, Fn fn) {
    const std::size_t n = recs.size();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const auto& range) {
        beat(pulse);
        std::size_t i = range.begin();
        while (i < range.end() && i > 0 && same_key(recs[i - 1], recs[i])) ++i;
        while (i < range.end()) {
            std::size_t j = i + 1;
            while (j < n && same_key(recs[i], recs[j])) ++j;
            fn(i, j);
            i = j;
        }
    });
}

template <int N>
std::vector<FaceState> match_faces(const std::vector<FaceRecord<N>>& recs, const FaceSlots& slots,
                                   ViolationSink& sink, const Pulse& pulse) {
    std::vector<FaceState> state(recs.size(), FaceState::Free);
    auto report = [&](ViolationKind kind, std::size_t i) {
        const ElementRef cell = slots.cell_of(slot_of(recs[i]));
        sink.add(kind, cell.set, cell.index);
    };
    for_each_run(recs, pulse, [&](std::size_t first, std::size_t last) {
        if (last - first == 1) return;
        if (last - first > 2) {
            for (std::size_t i = first; i < last; ++i) {
                state[i] = FaceState::Overshared;
                report(ViolationKind::FaceSharedByMany, i);
            }
            return;
        }
        state[first] = state[first + 1] = FaceState::Interior;
        const index_t a = form_of(recs[first]), b = form_of(recs[first + 1]);
        if ((a >> 1) != (b >> 1)) {  // same four nodes, different edges: quads that cross
            report(ViolationKind::NonMatchingFace, first);
            report(ViolationKind::NonMatchingFace, first + 1);
        } else if (a == b) {  // both cells on the same side of the face: they overlap
            report(ViolationKind::SameOrientation, first);
            report(ViolationKind::SameOrientation, first + 1);
        }
    });
    return state;
}

std::vector<std::uint32_t> indices_in_state(const std::vector<FaceState>& state, FaceState wanted) {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < state.size(); ++i)
        if (state[i] == wanted) out.push_back(static_cast<std::uint32_t>(i));
    return out;
}

// ---------------------------------------------------------------------------------------------
// Free triangles against free quads: a triangle whose three nodes are corners of one free quad
// covers part of it (the hex quad facing two tet triangles). Both sides are marked NonMatching.

std::array<index_t, 3> drop_one(const std::array<index_t, 4>& key, int k) {
    std::array<index_t, 3> t{};
    for (int i = 0, j = 0; i < 4; ++i)
        if (i != k) t[j++] = key[i];
    return t;
}

void match_triangles_to_quads(const std::vector<TriRecord>& tris, std::vector<FaceState>& tri_state,
                              const std::vector<QuadRecord>& quads, std::vector<FaceState>& quad_state,
                              const FaceSlots& tri_slots, const FaceSlots& quad_slots, ViolationSink& sink) {
    const std::vector<std::uint32_t> free_tris = indices_in_state(tri_state, FaceState::Free);
    const std::vector<std::uint32_t> free_quads = indices_in_state(quad_state, FaceState::Free);
    if (free_tris.empty() || free_quads.empty()) return;

    // Keys of free triangles are sorted already (a subsequence of sorted records).
    std::vector<std::array<index_t, 3>> tri_keys(free_tris.size());
    for (std::size_t i = 0; i < free_tris.size(); ++i) tri_keys[i] = tris[free_tris[i]].key;
    std::vector<std::array<index_t, 3>> corner_keys;
    corner_keys.reserve(4 * free_quads.size());
    for (std::uint32_t q : free_quads)
        for (int k = 0; k < 4; ++k) corner_keys.push_back(drop_one(quads[q].key, k));
    tbb::parallel_sort(corner_keys.begin(), corner_keys.end());

    tbb::parallel_for(std::size_t{0}, free_tris.size(), [&](std::size_t i) {
        if (!std::binary_search(corner_keys.begin(), corner_keys.end(), tri_keys[i])) return;
        tri_state[free_tris[i]] = FaceState::NonMatching;
        const ElementRef c = tri_slots.cell_of(slot_of(tris[free_tris[i]]));
        sink.add(ViolationKind::NonMatchingFace, c.set, c.index);
    });
    tbb::parallel_for(std::size_t{0}, free_quads.size(), [&](std::size_t i) {
        const QuadRecord& q = quads[free_quads[i]];
        for (int k = 0; k < 4; ++k) {
            if (!std::binary_search(tri_keys.begin(), tri_keys.end(), drop_one(q.key, k))) continue;
            quad_state[free_quads[i]] = FaceState::NonMatching;
            const ElementRef c = quad_slots.cell_of(slot_of(q));
            sink.add(ViolationKind::NonMatchingFace, c.set, c.index);
            return;
        }
    });
}

// ---------------------------------------------------------------------------------------------
// The boundary: free faces' area and edges.

// A quad's cycle from its record: the smallest node, a neighbour, the opposite node, the other
// neighbour. Orientation is not needed for areas and edges.
std::array<index_t, 4> quad_cycle(const QuadRecord& q) {
    const int opposite = static_cast<int>((form_of(q) >> 1) & 3);
    std::array<index_t, 4> c{q.key[0], 0, q.key[opposite], 0};
    int next = 1;
    for (int k = 1; k < 4; ++k)
        if (k != opposite) {
            c[next] = q.key[k];
            next = 3;
        }
    return c;
}

double quad_area(const HybridMesh& m, const std::array<index_t, 4>& c) {
    const Vec3 p0 = m.point(c[0]), p1 = m.point(c[1]), p2 = m.point(c[2]), p3 = m.point(c[3]);
    const double split02 = triangle_area(p0, p1, p2) + triangle_area(p0, p2, p3);
    const double split13 = triangle_area(p1, p2, p3) + triangle_area(p1, p3, p0);
    return std::min(split02, split13);
}

struct Boundary {
    std::vector<std::uint32_t> tris;   // indices of free triangle records
    std::vector<std::uint32_t> quads;  // indices of free quad records
};

double boundary_area(const HybridMesh& m, const Boundary& b, const std::vector<TriRecord>& tris,
                     const std::vector<QuadRecord>& quads) {
    const double tri_area = block_sum(static_cast<index_t>(b.tris.size()), [&](index_t i) {
        const auto& k = tris[b.tris[i]].key;
        return triangle_area(m.point(k[0]), m.point(k[1]), m.point(k[2]));
    });
    const double quad_area_sum = block_sum(static_cast<index_t>(b.quads.size()),
                                           [&](index_t i) { return quad_area(m, quad_cycle(quads[b.quads[i]])); });
    return tri_area + quad_area_sum;
}

// An edge of a boundary face: its nodes (a < b) and the face, numbered triangles first.
struct EdgeRecord {
    index_t a, b;
    std::uint32_t face;
    bool operator<(const EdgeRecord& o) const {
        return a != o.a ? a < o.a : b != o.b ? b < o.b : face < o.face;
    }
};

bool same_key(const EdgeRecord& x, const EdgeRecord& y) { return x.a == y.a && x.b == y.b; }

EdgeRecord edge(index_t u, index_t v, std::uint32_t face) { return {std::min(u, v), std::max(u, v), face}; }

// Every boundary edge must lie on exactly two boundary faces; the cells of the faces around
// any other edge are reported.
void check_watertight(const Boundary& b, const std::vector<TriRecord>& tris, const std::vector<QuadRecord>& quads,
                      const FaceSlots& tri_slots, const FaceSlots& quad_slots, ViolationSink& sink) {
    const std::size_t nt = b.tris.size(), nq = b.quads.size();
    std::vector<EdgeRecord> edges(3 * nt + 4 * nq);
    tbb::parallel_for(std::size_t{0}, nt, [&](std::size_t i) {
        const auto& k = tris[b.tris[i]].key;
        const auto f = static_cast<std::uint32_t>(i);
        edges[3 * i] = edge(k[0], k[1], f);
        edges[3 * i + 1] = edge(k[1], k[2], f);
        edges[3 * i + 2] = edge(k[0], k[2], f);
    });
    tbb::parallel_for(std::size_t{0}, nq, [&](std::size_t i) {
        const auto c = quad_cycle(quads[b.quads[i]]);
        const auto f = static_cast<std::uint32_t>(nt + i);
        for (int k = 0; k < 4; ++k) edges[3 * nt + 4 * i + k] = edge(c[k], c[(k + 1) % 4], f);
    });
    tbb::parallel_sort(edges.begin(), edges.end());
    for_each_run(edges, Pulse{}, [&](std::size_t first, std::size_t last) {
        if (last - first == 2) return;
        for (std::size_t i = first; i < last; ++i) {
            const std::uint32_t f = edges[i].face;
            const ElementRef c = f < nt ? tri_slots.cell_of(slot_of(tris[b.tris[f]]))
                                        : quad_slots.cell_of(slot_of(quads[b.quads[f - nt]]));
            sink.add(ViolationKind::OpenBoundary, c.set, c.index);
        }
    });
}

// ---------------------------------------------------------------------------------------------
// Stored boundary faces: each must be a boundary (free, matched) cell face, same orientation;
// an interface group's, an interior face (either way round).

template <int N>
void check_stored_faces(const HybridMesh& mesh, const std::vector<FaceRecord<N>>& recs,
                        const std::vector<FaceState>& state, ViolationSink& sink) {
    constexpr FaceKind kind = N == 3 ? FaceKind::Tri : FaceKind::Quad;
    constexpr ElementRef::Set set = N == 3 ? ElementRef::Set::BoundaryTri : ElementRef::Set::BoundaryQuad;
    std::vector<char> interface(mesh.surface_group_names.size(), 0);
    for (std::size_t g = 0; g < interface.size(); ++g) interface[g] = is_interface_group(mesh.surface_group_names[g]);
    const std::vector<index_t>& groups = mesh.block(kind).group;
    tbb::parallel_for(tbb::blocked_range<index_t>(0, mesh.face_count(kind)), [&](const auto& range) {
        for (index_t i = range.begin(); i != range.end(); ++i) {
            const std::span<const index_t> nodes = mesh.face(kind, i);
            std::array<index_t, N> cycle{};
            std::copy(nodes.begin(), nodes.end(), cycle.begin());
            const FaceRecord<N> stored = make_record<N>(cycle, 0);
            const auto [lo, hi] = std::equal_range(recs.begin(), recs.end(), stored, key_less<N>);
            const bool inner = groups[i] < interface.size() && interface[groups[i]];
            const FaceState found = hi - lo >= 1 ? state[static_cast<std::size_t>(lo - recs.begin())] : FaceState::Free;
            const bool on_cell = !repeats_a_node(nodes) &&
                                 (inner ? hi - lo == 2 && found == FaceState::Interior
                                        : hi - lo == 1 && found == FaceState::Free && form_of(*lo) == form_of(stored));
            if (!on_cell) sink.add(ViolationKind::BoundaryFaceNotOnCell, set, i);
        }
    });
}

}  // namespace

const char* violation_name(ViolationKind kind) {
    switch (kind) {
        case ViolationKind::NonPositiveVolume: return "NonPositiveVolume";
        case ViolationKind::DegenerateCell: return "DegenerateCell";
        case ViolationKind::FaceSharedByMany: return "FaceSharedByMany";
        case ViolationKind::SameOrientation: return "SameOrientation";
        case ViolationKind::NonMatchingFace: return "NonMatchingFace";
        case ViolationKind::OpenBoundary: return "OpenBoundary";
        case ViolationKind::BoundaryFaceNotOnCell: return "BoundaryFaceNotOnCell";
    }
    return "?";
}

const Violation* CheckReport::find(ViolationKind kind) const {
    for (const Violation& v : violations)
        if (v.kind == kind) return &v;
    return nullptr;
}

CheckReport check_mesh(const HybridMesh& mesh, const Pulse& pulse) {
    mesh.validate_layout();  // out-of-range node ids would make every step below undefined
    CheckReport report;
    ViolationSink sink;
    report.volume = check_cells(mesh, sink);
    beat(pulse);

    const FaceSlots tri_slots(mesh, Shape::Tri), quad_slots(mesh, Shape::Quad);
    const std::vector<TriRecord> tris = build_records<3>(mesh, tri_slots, pulse);
    beat(pulse);
    const std::vector<QuadRecord> quads = build_records<4>(mesh, quad_slots, pulse);
    beat(pulse);
    std::vector<FaceState> tri_state = match_faces(tris, tri_slots, sink, pulse);
    beat(pulse);
    std::vector<FaceState> quad_state = match_faces(quads, quad_slots, sink, pulse);
    beat(pulse);
    match_triangles_to_quads(tris, tri_state, quads, quad_state, tri_slots, quad_slots, sink);
    beat(pulse);

    const Boundary boundary{indices_in_state(tri_state, FaceState::Free),
                            indices_in_state(quad_state, FaceState::Free)};
    const auto interior = std::count(tri_state.begin(), tri_state.end(), FaceState::Interior) +
                          std::count(quad_state.begin(), quad_state.end(), FaceState::Interior);
    report.interior_faces = static_cast<index_t>(interior / 2);
    report.boundary_faces = static_cast<index_t>(boundary.tris.size() + boundary.quads.size());
    report.boundary_area = boundary_area(mesh, boundary, tris, quads);
    beat(pulse);
    check_watertight(boundary, tris, quads, tri_slots, quad_slots, sink);
    beat(pulse);

    check_stored_faces<3>(mesh, tris, tri_state, sink);
    beat(pulse);
    check_stored_faces<4>(mesh, quads, quad_state, sink);
    report.violations = sink.collect();
    return report;
}

std::string describe(const CheckReport& report) {
    static constexpr const char* kSetNames[] = {"tet", "pyramid", "hex", "boundary triangle", "boundary quad"};
    std::string out;
    for (const Violation& v : report.violations) {
        if (!out.empty()) out += '\n';
        out += std::string(violation_name(v.kind)) + ": " + std::to_string(v.count) + " (";
        for (std::size_t i = 0; i < v.first.size(); ++i) {
            if (i > 0) out += ", ";
            out += std::string(kSetNames[static_cast<int>(v.first[i].set)]) + " " + std::to_string(v.first[i].index);
        }
        if (v.count > v.first.size()) out += ", ...";
        out += ')';
    }
    return out;
}

}  // namespace tubemesh
