#include "engine/quality/quality.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/quality/standard_measures.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace tubemesh {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------
// Scaled Jacobian at one corner, shared by the hex and the pyramid's tets.

// det(e1, e2, e3) / (|e1||e2||e3|): the sine-like volume of the corner, in [-1, 1]. A
// zero-length edge collapses the corner, so it scores 0 rather than 0/0.
double corner_scaled_jacobian(const Vec3& e1, const Vec3& e2, const Vec3& e3) {
    const double lengths = std::sqrt(norm2(e1) * norm2(e2) * norm2(e3));
    if (!(lengths > 0)) return 0.0;
    return det3(e1, e2, e3) / lengths;
}

// |A|_F · |A^-1|_F / 3 for A = [e1 e2 e3]. A^-1 = adj(A) / det and the rows of adj(A) are
// e2×e3, e3×e1, e1×e2, so no inversion is needed. A corner that is not positively oriented
// has no meaningful condition number (|det| would hide an inversion): +infinity.
double corner_condition(const Vec3& e1, const Vec3& e2, const Vec3& e3) {
    const Vec3 c23 = cross(e2, e3);
    const double det = dot(e1, c23);
    if (!(det > 0)) return kInfinity;
    const double frob2 = norm2(e1) + norm2(e2) + norm2(e3);
    const double adj_frob2 = norm2(c23) + norm2(cross(e3, e1)) + norm2(cross(e1, e2));
    return std::sqrt(frob2 * adj_frob2) / (3.0 * det);
}

// For each hex corner: the corner, then its three neighbours ordered so that (e1, e2, e3) is
// right-handed in VTK order (bottom 0-1-2-3 counter-clockwise seen from the top, 4 above 0):
// at a bottom corner (next, previous, up), at a top corner (previous, next, down).
constexpr std::array<std::array<std::uint8_t, 4>, 8> kHexCorners{{{0, 1, 3, 4},
                                                                  {1, 2, 0, 5},
                                                                  {2, 3, 1, 6},
                                                                  {3, 0, 2, 7},
                                                                  {4, 7, 5, 0},
                                                                  {5, 4, 6, 1},
                                                                  {6, 5, 7, 2},
                                                                  {7, 6, 4, 3}}};

// ---------------------------------------------------------------------------------------
// Pyramid: Verdict's split along both base diagonals. In each tet (a, b, c, d) the triangle
// a-b-c is half of the base and runs counter-clockwise seen from the apex d, as the base
// 0-1-2-3 does, so (b-a, c-a, d-a) is right-handed whenever the pyramid is valid.
constexpr std::array<std::array<std::uint8_t, 4>, 4> kPyramidTets{{{0, 1, 2, 4},
                                                                   {0, 2, 3, 4},
                                                                   {0, 1, 3, 4},
                                                                   {1, 2, 3, 4}}};

// min over the four corners of det / (product of the three edge lengths at the corner).
// The determinant is the same (6 V) at every corner of a tet, so only the length products
// differ. Verdict's tet scaled Jacobian is this times sqrt(2) (1 for the regular tet).
double tet_min_corner_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const double ab = norm2(b - a), ac = norm2(c - a), ad = norm2(d - a);
    const double bc = norm2(c - b), bd = norm2(d - b), cd = norm2(d - c);
    const std::array<double, 4> lengths{std::sqrt(ab * ac * ad), std::sqrt(ab * bc * bd),
                                        std::sqrt(ac * bc * cd), std::sqrt(ad * bd * cd)};
    const double det = det3(b - a, c - a, d - a);
    double ratio = kInfinity;
    for (double l : lengths) ratio = std::min(ratio, l > 0 ? det / l : 0.0);
    return ratio;
}

// ---------------------------------------------------------------------------------------
// Per-cell loops.

// Cells per TBB task: the per-cell work is tens of flops, so tasks must be large enough for
// the scheduling cost to vanish.
constexpr std::size_t kCellGrain = 4096;

template <std::size_t N>
std::array<Vec3, N> gather(const HybridMesh& mesh, const index_t* nodes) {
    std::array<Vec3, N> p;
    for (std::size_t k = 0; k < N; ++k) p[k] = {mesh.x[nodes[k]], mesh.y[nodes[k]], mesh.z[nodes[k]]};
    return p;
}

// Calls f(i, points of cell i) for every cell of kind K, in parallel. f writes only slot i
// of its outputs, so the result does not depend on the scheduling.
template <CellKind K, class F>
void for_each_cell(const HybridMesh& mesh, F&& f) {
    constexpr std::size_t n = static_cast<std::size_t>(node_count(K));
    const index_t* nodes = mesh.block(K).nodes.data();
    const std::size_t count = mesh.block(K).nodes.size() / n;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, kCellGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) f(i, gather<n>(mesh, nodes + n * i));
                      });
}

template <CellKind K, class Measure>
std::vector<double> measure_cells(const HybridMesh& mesh, Measure measure) {
    std::vector<double> out(mesh.block(K).nodes.size() / static_cast<std::size_t>(node_count(K)));
    for_each_cell<K>(mesh, [&](std::size_t i, const auto& p) { out[i] = measure(p); });
    return out;
}

// ---------------------------------------------------------------------------------------
// Summaries. The values are cut into chunks of a fixed size, each chunk is summarised on
// its own (in parallel) and the chunks are combined in index order. Chunk boundaries and
// the order of every floating-point addition are then fixed by the cell count alone, so the
// mean is bit-identical for any number of threads.

constexpr std::size_t kSummaryChunk = 16384;
// Cells measured between two pulses (from whichever thread measures them).
constexpr std::size_t kPulseCells = 1 << 16;
constexpr int kClasses = 10;

// Class k holds [lo + k·w, lo + (k+1)·w) with w = (hi - lo) / 10; the last class also holds
// hi and everything above, the first everything below lo (and NaN, which cannot reach an
// index). (v - lo)·10 is formed before the division so that decimal class bounds such as
// 1.3 on [1, 4] land in the upper class, as a reader of the table expects.
int histogram_class(double v, double lo, double hi) {
    if (!(v > lo)) return 0;
    if (v >= hi) return kClasses - 1;
    return std::min(kClasses - 1, static_cast<int>((v - lo) * kClasses / (hi - lo)));
}

struct Partial {
    index_t count = 0;
    double sum = 0, min = kInfinity, max = -kInfinity;
    std::array<index_t, kClasses> histogram{};
};

Partial summarize_chunk(const double* v, std::size_t n, double lo, double hi) {
    Partial p;
    p.count = static_cast<index_t>(n);
    for (std::size_t i = 0; i < n; ++i) {
        p.sum += v[i];
        p.min = std::min(p.min, v[i]);
        p.max = std::max(p.max, v[i]);
        ++p.histogram[static_cast<std::size_t>(histogram_class(v[i], lo, hi))];
    }
    return p;
}

MeasureSummary summarize(const std::vector<double>& values, double lo, double hi) {
    MeasureSummary s;
    s.lo = lo;
    s.hi = hi;
    if (values.empty()) return s;

    const std::size_t chunks = (values.size() + kSummaryChunk - 1) / kSummaryChunk;
    std::vector<Partial> partial(chunks);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        const std::size_t begin = c * kSummaryChunk;
        const std::size_t end = std::min(values.size(), begin + kSummaryChunk);
        partial[c] = summarize_chunk(values.data() + begin, end - begin, lo, hi);
    });

    Partial total;
    for (const Partial& p : partial) {
        total.count += p.count;
        total.sum += p.sum;
        total.min = std::min(total.min, p.min);
        total.max = std::max(total.max, p.max);
        for (std::size_t k = 0; k < total.histogram.size(); ++k) total.histogram[k] += p.histogram[k];
    }
    s.count = total.count;
    s.min = total.min;
    s.max = total.max;
    s.mean = total.sum / static_cast<double>(total.count);
    s.histogram = total.histogram;
    return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Per element.

HexQuality hex_quality(const std::array<Vec3, 8>& p) {
    HexQuality q{kInfinity, 0.0};
    for (const auto& c : kHexCorners) {
        const Vec3 e1 = p[c[1]] - p[c[0]], e2 = p[c[2]] - p[c[0]], e3 = p[c[3]] - p[c[0]];
        q.scaled_jacobian = std::min(q.scaled_jacobian, corner_scaled_jacobian(e1, e2, e3));
        q.condition = std::max(q.condition, corner_condition(e1, e2, e3));
    }
    return q;
}

// Verdict (V_PyramidMetric.cpp, pyramid_scaled_jacobian): s = the smallest Verdict tet
// scaled Jacobian of the four tets, sqrt(2) · min_corners det / (l1 l2 l3); x = s · sqrt(2),
// i.e.
//     x = 2 · min over the 4 tets and their 4 corners of det / (l1 l2 l3),
//     measure = x if x < 1 else 2 - x.
// This normalisation gives both reference values of docs/architecture.md:
//  * all edges equal (unit base, apex height 1/sqrt(2)): the worst tet corner is a base
//    corner on a diagonal, det / (1 · sqrt(2) · 1) = (1/sqrt(2)) / sqrt(2) = 1/2, so x = 1;
//  * the paper's ideal apex, height H = 0.98154 over a unit base: the worst corner is the
//    apex, with three edges of length L = sqrt(1/2 + H²); x = 2H / L³ = 1.108879, measure
//    2 - x = 0.891121.
// Unlike Verdict, which clamps to 0, an inverted or twisted pyramid keeps its negative
// value, like the tet and hex measures, so the minimum shows how bad it is.
double pyramid_scaled_jacobian(const std::array<Vec3, 5>& p) {
    double ratio = kInfinity;
    for (const auto& t : kPyramidTets)
        ratio = std::min(ratio, tet_min_corner_ratio(p[t[0]], p[t[1]], p[t[2]], p[t[3]]));
    const double x = 2.0 * ratio;
    return x < 1.0 ? x : 2.0 - x;
}

// ---------------------------------------------------------------------------------------
// Per mesh.

std::vector<double> cell_quality(const HybridMesh& mesh, CellKind kind) {
    switch (kind) {
        case CellKind::Tet:
            return measure_cells<CellKind::Tet>(mesh, [](const auto& p) { return tet_collapse(p); });
        case CellKind::Pyramid:
            return measure_cells<CellKind::Pyramid>(mesh,
                                                    [](const auto& p) { return pyramid_scaled_jacobian(p); });
        case CellKind::Hex:
            return measure_cells<CellKind::Hex>(mesh,
                                                [](const auto& p) { return hex_quality(p).scaled_jacobian; });
    }
    return {};
}

std::vector<double> hex_condition_numbers(const HybridMesh& mesh) {
    return measure_cells<CellKind::Hex>(mesh, [](const auto& p) { return hex_quality(p).condition; });
}

std::vector<double> cell_measure(const HybridMesh& mesh, CellKind kind, CellMeasure measure) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    switch (measure) {
        case CellMeasure::Primary: return cell_quality(mesh, kind);
        case CellMeasure::ScaledJacobian:
            if (kind == CellKind::Tet) return measure_cells<CellKind::Tet>(mesh, tet_scaled_jacobian);
            if (kind == CellKind::Hex) return measure_cells<CellKind::Hex>(mesh, hex_verdict_scaled_jacobian);
            return cell_quality(mesh, kind);
        case CellMeasure::MinDihedral:
            if (kind == CellKind::Tet) return measure_cells<CellKind::Tet>(mesh, tet_min_dihedral_degrees);
            break;
        case CellMeasure::AspectRatio:
            if (kind == CellKind::Tet) return measure_cells<CellKind::Tet>(mesh, tet_aspect_ratio);
            break;
        case CellMeasure::Condition:
            if (kind == CellKind::Hex) return hex_condition_numbers(mesh);
            break;
    }
    return std::vector<double>(mesh.cell_count(kind), nan);
}

QualitySummary summarize_quality(const HybridMesh& mesh, const Pulse& pulse) {
    QualitySummary s;
    s.pyramid_jacobian = summarize(cell_quality(mesh, CellKind::Pyramid), 0.0, 1.0);
    beat(pulse);

    // One pass per kind for all its measures.
    const std::size_t tets = mesh.block(CellKind::Tet).nodes.size() / 4;
    std::vector<double> collapse(tets), tet_jacobian(tets), dihedral(tets), aspect(tets);
    for_each_cell<CellKind::Tet>(mesh, [&](std::size_t i, const std::array<Vec3, 4>& p) {
        if (i % kPulseCells == 0) beat(pulse);
        collapse[i] = tet_collapse(p);
        tet_jacobian[i] = tet_scaled_jacobian(p);
        dihedral[i] = tet_min_dihedral_degrees(p);
        aspect[i] = tet_aspect_ratio(p);
    });
    // Each measure's summary sorts its values: a beat before each.
    const auto summarized = [&](const std::vector<double>& values, double lo, double hi) {
        beat(pulse);
        return summarize(values, lo, hi);
    };
    s.tet_collapse = summarized(collapse, 0.0, 1.0);
    s.tet_scaled_jacobian = summarized(tet_jacobian, 0.0, 1.0);
    s.tet_min_dihedral = summarized(dihedral, 0.0, 90.0);
    s.tet_aspect_ratio = summarized(aspect, 1.0, 4.0);
    beat(pulse);

    const std::size_t hexes = mesh.block(CellKind::Hex).nodes.size() / 8;
    std::vector<double> jacobian(hexes), condition(hexes), verdict(hexes);
    for_each_cell<CellKind::Hex>(mesh, [&](std::size_t i, const std::array<Vec3, 8>& p) {
        const HexQuality q = hex_quality(p);
        jacobian[i] = q.scaled_jacobian;
        condition[i] = q.condition;
        verdict[i] = std::min(q.scaled_jacobian, hex_centre_scaled_jacobian(p));
    });
    s.hex_scaled_jacobian = summarized(jacobian, 0.0, 1.0);
    s.hex_condition = summarized(condition, 1.0, 4.0);
    s.hex_verdict_jacobian = summarized(verdict, 0.0, 1.0);
    return s;
}

}  // namespace tubemesh
