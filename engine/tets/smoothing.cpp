#include "engine/tets/smoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <tbb/parallel_for.h>

#include "engine/mesh/vec3_ops.hpp"
#include "engine/predicates/predicates_inline.hpp"
#include "engine/tets/tet_neighbourhood.hpp"

namespace tubemesh::tets {

namespace {

// Point -> tets incidence as offsets + indices, tets in increasing order for every point.
struct Incidence {
    std::vector<index_t> offsets;
    std::vector<index_t> tets;
    std::span<const index_t> of(index_t p) const { return {tets.data() + offsets[p], offsets[p + 1] - offsets[p]}; }
};

Incidence build_incidence(const TetDomain& dom) {
    Incidence inc;
    const index_t points = dom.point_count();
    inc.offsets.assign(std::size_t{points} + 1, 0);
    const auto v = dom.tets.vertices();
    for (index_t p : v) ++inc.offsets[p + 1];
    for (index_t p = 0; p < points; ++p) inc.offsets[p + 1] += inc.offsets[p];
    inc.tets.resize(v.size());
    std::vector<index_t> fill(inc.offsets.begin(), inc.offsets.end() - 1);
    for (std::size_t k = 0; k < v.size(); ++k) inc.tets[fill[v[k]]++] = static_cast<index_t>(k / 4);
    return inc;
}

// Greedy colouring in point order: a colour never holds two points of one tet.
std::vector<std::vector<index_t>> colour_points(const TetDomain& dom, const Incidence& inc) {
    const index_t points = dom.point_count();
    std::vector<std::uint32_t> colour(points, kNoIndex);
    std::vector<index_t> seen;  // seen[c] == p: colour c is taken by a neighbour of p
    std::vector<std::vector<index_t>> classes;
    for (index_t p = dom.front_points; p < points; ++p) {
        const auto star = inc.of(p);
        if (star.empty()) continue;
        for (index_t t : star)
            for (index_t i = 0; i < 4; ++i) {
                const index_t q = dom.tets.vertex(t)[i];
                if (q != p && colour[q] != kNoIndex) seen[colour[q]] = p;
            }
        std::uint32_t c = 0;
        while (c < seen.size() && seen[c] == p) ++c;
        if (c == seen.size()) {
            seen.push_back(kNoIndex);
            classes.emplace_back();
        }
        colour[p] = c;
        classes[c].push_back(p);
    }
    return classes;
}

// The smallest collapse and the sum of collapses of the tets around p with p placed at x
// (nullptr: where it is).
struct StarQuality {
    double worst = std::numeric_limits<double>::infinity();
    double sum = 0;
};

StarQuality star_quality(const TetDomain& dom, index_t p, std::span<const index_t> star, const Vec3* x) {
    StarQuality s;
    for (index_t t : star) {
        const index_t* v = dom.tets.vertex(t);
        std::array<Vec3, 4> c;
        for (int i = 0; i < 4; ++i) c[i] = (x && v[i] == p) ? *x : point_vec(dom, v[i]);
        const double q = tet_collapse(c);
        s.worst = std::min(s.worst, q);
        s.sum += q;
    }
    return s;
}

bool none_inverted(const TetDomain& dom, index_t p, std::span<const index_t> star, const Vec3& x) {
    const double moved[3] = {x.x, x.y, x.z};
    for (index_t t : star) {
        const index_t* v = dom.tets.vertex(t);
        std::array<const double*, 4> c;
        for (int i = 0; i < 4; ++i) c[i] = v[i] == p ? moved : dom.point(v[i]);
        if (predicates::orient3d_inline(c[0], c[1], c[2], c[3]) <= 0) return false;
    }
    return true;
}

// Where p would make tet t regular over its opposite face: above the face's centroid, at the
// regular tet's height for the face's mean edge length, on p's side.
Vec3 regular_apex(const TetDomain& dom, index_t t, index_t p) {
    const index_t* v = dom.tets.vertex(t);
    const int lp = local_index(dom, t, p);
    const auto& f = kTetFaceToward[lp];
    const Vec3 a = point_vec(dom, v[f[0]]), b = point_vec(dom, v[f[1]]), c = point_vec(dom, v[f[2]]);
    const Vec3 normal = cross(b - a, c - a);  // toward p: (a, b, c, p) is positive
    const double len = norm(normal);
    const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
    if (!(len > 0)) return centroid;
    const double edge = (norm(b - a) + norm(c - b) + norm(a - c)) / 3.0;
    return centroid + (std::sqrt(2.0 / 3.0) * edge / len) * normal;
}

// The volume-weighted mean of the star's circumcentres: the optimal-Delaunay (ODT) position of
// p (Chen and Holst), which spreads points evenly where the centroid only averages them.
Vec3 odt_target(const TetDomain& dom, std::span<const index_t> star, const Vec3& fallback) {
    Vec3 sum{0, 0, 0};
    double weight = 0;
    for (index_t t : star) {
        const index_t* v = dom.tets.vertex(t);
        const Vec3 a = point_vec(dom, v[0]);
        const Vec3 b = point_vec(dom, v[1]) - a, c = point_vec(dom, v[2]) - a, d = point_vec(dom, v[3]) - a;
        const double det = dot(b, cross(c, d));
        if (!(det > 0)) continue;
        const Vec3 centre = a + (0.5 / det) * (norm2(b) * cross(c, d) + norm2(c) * cross(d, b) + norm2(d) * cross(b, c));
        sum = sum + det * centre;
        weight += det;
    }
    return weight > 0 ? (1.0 / weight) * sum : fallback;
}

// A mean-raising move may lower the star's worst tet, but never below this (nor below where
// it already is): well above the 0.30 the tet step promises as its minimum.
constexpr double kLaplacianFloor = 0.45;

// Two kinds of move, the first that applies wins: one that raises the worst tet of the star
// (towards the neighbours' centroid, the ODT position or the worst tet's regular apex), else
// one towards the ODT position or the centroid that raises the star's total collapse and keeps
// its worst tet above min(its value, kLaplacianFloor). Worst-tet moves alone leave the bulk of
// the mesh where refinement put it; the second kind (the paper's Laplacian smoothing) is what
// raises the mean.
bool try_move(TetDomain& dom, index_t p, std::span<const index_t> star, double threshold, double min_gain) {
    StarQuality now;
    index_t worst_tet = star[0];
    for (index_t t : star) {
        const index_t* v = dom.tets.vertex(t);
        const double q = collapse_of(dom, v[0], v[1], v[2], v[3]);
        now.sum += q;
        if (q < now.worst) {
            now.worst = q;
            worst_tet = t;
        }
    }
    if (!(now.worst < threshold)) return false;

    const Vec3 here = point_vec(dom, p);
    Vec3 centroid{0, 0, 0};
    for (index_t t : star)
        for (int i = 0; i < 4; ++i) {
            const index_t q = dom.tets.vertex(t)[i];
            if (q != p) centroid = centroid + point_vec(dom, q);
        }
    centroid = (1.0 / (3.0 * static_cast<double>(star.size()))) * centroid;
    const Vec3 odt = odt_target(dom, star, centroid);
    const std::array<Vec3, 3> targets{centroid, odt, regular_apex(dom, worst_tet, p)};
    constexpr double kSteps[] = {1.0, 0.5, 0.25, 0.125};

    double best = now.worst + min_gain;
    Vec3 best_x = here;
    bool improved = false;
    for (const Vec3& target : targets) {
        for (double step : kSteps) {
            const Vec3 x = here + step * (target - here);
            const double q = star_quality(dom, p, star, &x).worst;
            if (q > best) {
                best = q;
                best_x = x;
                improved = true;
            }
        }
    }
    if (!improved) {
        double best_sum = now.sum + min_gain * static_cast<double>(star.size());
        for (const Vec3& target : {odt, centroid})
            for (double step : kSteps) {
                const Vec3 x = here + step * (target - here);
                const StarQuality q = star_quality(dom, p, star, &x);
                if (q.worst >= std::min(now.worst, kLaplacianFloor) && q.sum > best_sum) {
                    best_sum = q.sum;
                    best_x = x;
                    improved = true;
                }
            }
    }
    if (!improved || !none_inverted(dom, p, star, best_x)) return false;
    double* c = dom.xyz.data() + std::size_t{3} * p;
    c[0] = best_x.x;
    c[1] = best_x.y;
    c[2] = best_x.z;
    return true;
}

}  // namespace

SmoothingCounts smooth_points(TetDomain& dom, int sweeps, double threshold, double min_gain) {
    SmoothingCounts counts;
    const Incidence inc = build_incidence(dom);
    const auto classes = colour_points(dom, inc);
    counts.colours = classes.size();
    std::vector<std::uint8_t> moved;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        std::uint64_t moves = 0;
        for (const auto& points : classes) {
            moved.assign(points.size(), 0);
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 64),
                              [&](const tbb::blocked_range<std::size_t>& r) {
                                  for (std::size_t i = r.begin(); i != r.end(); ++i)
                                      moved[i] = try_move(dom, points[i], inc.of(points[i]), threshold, min_gain);
                              });
            for (auto m : moved) moves += m;
        }
        counts.moves += moves;
        if (moves == 0) break;
    }
    return counts;
}

}  // namespace tubemesh::tets
