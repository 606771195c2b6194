#include "engine/surface/surface_optimisation.hpp"
#include "engine/core/vec3_ops.hpp"

#include <algorithm>
#include <cmath>

#include "engine/surface/uv_predicates.hpp"

namespace tubemesh::surface {

namespace {


// The largest cosine among the triangle's angles: the smallest angle, without an acos.
double max_cosine(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, bc = c - b, ca = a - c;
    const double lab = std::sqrt(dot(ab, ab)), lbc = std::sqrt(dot(bc, bc)), lca = std::sqrt(dot(ca, ca));
    if (!(lab > 0 && lbc > 0 && lca > 0)) return 1.0;
    const double ca_ = -dot(ca, ab) / (lca * lab), cb = -dot(ab, bc) / (lab * lbc), cc = -dot(bc, ca) / (lbc * lca);
    return std::max({ca_, cb, cc});
}


// Flips and moves only touch triangles with an angle under 50 degrees: the rest are already
// better than the surface's 40 degree bar and leaving them alone makes a pass cheap.
constexpr double kGoodCosine = 0.6427876096865394;  // cos 50°

// Neighbouring triangles whose sizes (mean edge lengths) differ by more than this are evened out.
constexpr double kGradingRatio = 1.4;
// ... as long as no angle of the moved vertex's fan drops below this (or below the fan's worst).
// 35 degrees left pairs over the surface's grading that only a move through a narrower fan
// evens out; such moves are rare (bench/results/tuning-notes.md).
constexpr double kGradingCosine = 0.8660254037844386;  // cos 30°

double mean_edge(const Vec3& a, const Vec3& b, const Vec3& c) {
    return (std::sqrt(dot(b - a, b - a)) + std::sqrt(dot(c - b, c - b)) +
            std::sqrt(dot(a - c, a - c))) / 3;
}

// The size ratio reported around a vertex next to a pole: never improved on, so never moved.
constexpr double kUnknownRatio = 1e30;

// Triangles with an angle under 30 degrees are worth removing a vertex for.
constexpr double kCollapseBelow = 0.8660254037844386;  // cos 30°

// The uv step whose image under the surface's tangent map best matches the move r in space
// (one Gauss-Newton step of the projection onto the surface).
bool tangent_step(const SurfaceDerivatives& d, const Vec3& r, Uv& step) {
    const double a = dot(d.du, d.du), b = dot(d.du, d.dv), c = dot(d.dv, d.dv);
    const double ru = dot(d.du, r), rv = dot(d.dv, r);
    const double det = a * c - b * b;
    if (!(det > 1e-14 * a * c) || !(det > 0)) return false;
    step = {(c * ru - b * rv) / det, (a * rv - b * ru) / det};
    return true;
}

}  // namespace

// A triangle with two occurrences of one node (on a pole's degenerate edge) is no triangle in
// space: it is left out of the result, so it counts as perfect here (quality -1, size 0).
void SurfaceOptimiser::update_quality(const UvMesh& mesh, index_t t) {
    const index_t i = mesh.vertex(t, 0), j = mesh.vertex(t, 1), k = mesh.vertex(t, 2);
    if (mesh.node[i] == mesh.node[j] || mesh.node[j] == mesh.node[k] || mesh.node[k] == mesh.node[i]) {
        quality_[t] = -1;
        size_[t] = 0;
        return;
    }
    const auto& x = mesh.xyz;
    quality_[t] = max_cosine(x[i], x[j], x[k]);
    size_[t] = mean_edge(x[i], x[j], x[k]);
}

bool SurfaceOptimiser::fan_faces_out(const UvMesh& mesh, index_t v, const Vec3& at) const {
    const std::size_t n = ring_.size();
    for (std::size_t j = 0; j < n; ++j) {
        const index_t p = ring_[j], q = ring_[(j + 1) % n];
        if (!mesh.faces_out(v, p, q, at, mesh.xyz[p], mesh.xyz[q])) return false;
    }
    return true;
}

double SurfaceOptimiser::fan_cosine(const UvMesh& mesh, const Vec3& at, std::size_t j) const {
    const index_t p = ring_[j], q = ring_[(j + 1) % ring_.size()];
    if (mesh.node[p] == mesh.node[q]) return -1;  // collapsed onto a pole: not output
    return max_cosine(at, mesh.xyz[p], mesh.xyz[q]);
}

bool SurfaceOptimiser::try_flip(UvMesh& mesh, index_t t, int i) {
    const index_t n = mesh.neighbor(t, i);
    if (mesh.constrained(t, i) || n == kNoIndex) return false;
    const double before = std::max(quality_[t], quality_[n]);
    if (before <= kGoodCosine) return false;
    const auto& x = mesh.xyz;
    const index_t c = mesh.vertex(t, i), a = mesh.vertex(t, next3(i)), b = mesh.vertex(t, prev3(i));
    const index_t d = mesh.vertex(n, static_cast<int>(mesh.adj[3 * t + i] % 3));
    // Never join two occurrences of one node, nor flip next to a pole's degenerate triangles.
    const index_t na = mesh.node[a], nb = mesh.node[b], nc = mesh.node[c], nd = mesh.node[d];
    if (nc == nd || na == nb || na == nc || na == nd || nb == nc || nb == nd) return false;
    const double after = std::max(max_cosine(x[c], x[a], x[d]), max_cosine(x[d], x[b], x[c]));
    if (!(after < before - 1e-9)) return false;
    // Two triangles valid in uv can still fold over in space (large ones on a curved face).
    if (!mesh.faces_out(c, a, d, x[c], x[a], x[d]) || !mesh.faces_out(d, b, c, x[d], x[b], x[c])) return false;
    if (!mesh.flip(t, i)) return false;  // not convex in uv
    update_quality(mesh, t);
    update_quality(mesh, n);
    return true;
}

index_t SurfaceOptimiser::flip_sweep(UvMesh& mesh) {
    index_t flips = 0;
    for (index_t t = 0; t < mesh.slot_count(); ++t) {
        if (mesh.dead(t) || !mesh.inside(t)) continue;
        for (int i = 0; i < 3; ++i) flips += try_flip(mesh, t, i);
    }
    return flips;
}

bool SurfaceOptimiser::gather_ring(const UvMesh& mesh, index_t v) {
    ring_.clear();
    fan_.clear();
    const index_t start = mesh.vtri[v];
    if (start == kNoIndex) return false;  // removed by a collapse
    index_t t = start;
    do {
        const int k = mesh.local_index(t, v);
        if (!mesh.inside(t)) return false;
        ring_.push_back(mesh.vertex(t, next3(k)));
        fan_.push_back(t);
        t = mesh.neighbor(t, next3(k));
        if (ring_.size() > 64) return false;  // not an ordinary interior vertex: leave it
    } while (t != kNoIndex && t != start);
    return t == start && ring_.size() >= 3;
}

double SurfaceOptimiser::fan_worst() const {
    double worst = -1;
    for (index_t t : fan_) worst = std::max(worst, quality_[t]);
    return worst;
}

bool SurfaceOptimiser::try_smooth(const SurfaceMap& surface, UvMesh& mesh, index_t v) {
    if (!gather_ring(mesh, v)) return false;
    double best = fan_worst();
    if (best <= kGoodCosine) return false;
    const std::size_t n = ring_.size();
    const auto& x = mesh.xyz;
    const SurfaceDerivatives d = surface.derivatives(mesh.uv[v]);
    const Vec3 normal = cross(d.du, d.dv);
    // Two proposals: the neighbours' centroid (Laplacian), and the mean of the points that
    // would make each opposite edge's triangle equilateral, which pulls harder on the bad
    // triangles a Laplacian leaves where fronts met.
    Vec3 centroid{0, 0, 0}, apexes{0, 0, 0};
    std::size_t edges = 0;
    for (std::size_t j = 0; j < n; ++j) {
        const Vec3 &p = x[ring_[j]], &q = x[ring_[(j + 1) % n]];
        centroid = {centroid.x + p.x, centroid.y + p.y, centroid.z + p.z};
        if (mesh.node[ring_[j]] == mesh.node[ring_[(j + 1) % n]]) continue;  // a pole's: no edge in space
        const Vec3 e = q - p;
        const Vec3 side = cross(normal, e);  // in the tangent plane, towards v (counter-clockwise fan)
        const double len_side = std::sqrt(dot(side, side)), len_e = std::sqrt(dot(e, e));
        if (!(len_side > 0)) return false;
        const double s = 0.8660254037844386 * len_e / len_side;
        apexes = {apexes.x + 0.5 * (p.x + q.x) + s * side.x, apexes.y + 0.5 * (p.y + q.y) + s * side.y,
                  apexes.z + 0.5 * (p.z + q.z) + s * side.z};
        ++edges;
    }
    if (edges == 0) return false;
    const double inv = 1.0 / double(n), inv_edges = 1.0 / double(edges);
    const Vec3 targets[2] = {{centroid.x * inv, centroid.y * inv, centroid.z * inv},
                             {apexes.x * inv_edges, apexes.y * inv_edges, apexes.z * inv_edges}};
    Uv best_uv = mesh.uv[v];
    Vec3 best_x = x[v];
    for (const Vec3& target : targets) {
        Uv step;
        if (!tangent_step(d, target - x[v], step)) continue;
        const Uv uv{mesh.uv[v].u + step.u, mesh.uv[v].v + step.v};
        bool valid = true;
        for (std::size_t j = 0; j < n && valid; ++j)
            valid = orient2d(uv, mesh.uv[ring_[j]], mesh.uv[ring_[(j + 1) % n]]) > 0;
        if (!valid) continue;
        const Vec3 moved = surface.point(uv);
        if (!fan_faces_out(mesh, v, moved)) continue;
        double worst = -1;
        for (std::size_t j = 0; j < n && worst < best; ++j) worst = std::max(worst, fan_cosine(mesh, moved, j));
        if (worst < best) best = worst, best_uv = uv, best_x = moved;
    }
    if (best_uv.u == mesh.uv[v].u && best_uv.v == mesh.uv[v].v) return false;
    mesh.uv[v] = best_uv;
    mesh.xyz[v] = best_x;
    for (index_t t : fan_) update_quality(mesh, t);
    return true;
}

index_t SurfaceOptimiser::smooth_sweep(const SurfaceMap& surface, index_t first_movable, UvMesh& mesh) {
    // The movable vertices of poor triangles, each once, in ascending order (deterministic).
    if (vertex_mark_.size() < mesh.vertex_count()) vertex_mark_.resize(mesh.vertex_count(), 0);
    ++vertex_epoch_;
    work_.clear();
    for (index_t t = 0; t < mesh.slot_count(); ++t) {
        if (mesh.dead(t) || !mesh.inside(t) || quality_[t] <= kGoodCosine) continue;
        for (int i = 0; i < 3; ++i) {
            const index_t v = mesh.vertex(t, i);
            if (v < first_movable || vertex_mark_[v] == vertex_epoch_) continue;
            vertex_mark_[v] = vertex_epoch_;
            work_.push_back(v);
        }
    }
    std::sort(work_.begin(), work_.end());
    index_t moves = 0;
    for (index_t v : work_) moves += try_smooth(surface, mesh, v);
    return moves;
}

bool SurfaceOptimiser::try_collapse(index_t v, index_t w, UvMesh& mesh) {
    if (!gather_ring(mesh, v)) return false;
    const std::size_t n = ring_.size();
    const std::size_t k = static_cast<std::size_t>(std::find(ring_.begin(), ring_.end(), w) - ring_.begin());
    if (k == n) return false;
    const auto& x = mesh.xyz;
    const double before = fan_worst();
    double after = -1;
    for (std::size_t j = 0; j < n; ++j) {
        if (j == (k + n - 1) % n || j == k) continue;
        const index_t p = ring_[j], q = ring_[(j + 1) % n];
        if (orient2d(mesh.uv[w], mesh.uv[p], mesh.uv[q]) <= 0) return false;
        if (mesh.node[w] == mesh.node[p] || mesh.node[w] == mesh.node[q]) return false;
        if (mesh.node[p] == mesh.node[q]) continue;  // stays collapsed onto its pole
        if (!mesh.faces_out(w, p, q, x[w], x[p], x[q])) return false;
        after = std::max(after, max_cosine(x[w], x[p], x[q]));
    }
    if (!(after < before)) return false;
    mesh.collapse_unchecked(v, ring_, fan_, k);
    for (std::size_t j = 0; j < n; ++j)
        if (j != (k + n - 1) % n && j != k) update_quality(mesh, fan_[j]);
    return true;
}

index_t SurfaceOptimiser::collapse_sweep(index_t first_movable, UvMesh& mesh) {
    index_t collapses = 0;
    const auto& x = mesh.xyz;
    for (index_t t = 0; t < mesh.slot_count(); ++t) {
        if (mesh.dead(t) || !mesh.inside(t) || quality_[t] <= kCollapseBelow) continue;
        const index_t a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
        // The shortest edge of a bad triangle is the one a collapse can remove.
        const double lab = dot(x[b] - x[a], x[b] - x[a]), lbc = dot(x[c] - x[b], x[c] - x[b]);
        const double lca = dot(x[a] - x[c], x[a] - x[c]);
        index_t p = a, q = b;
        if (lbc <= lab && lbc <= lca) p = b, q = c;
        else if (lca <= lab && lca <= lbc) p = c, q = a;
        if ((p >= first_movable && try_collapse(p, q, mesh)) || (q >= first_movable && try_collapse(q, p, mesh)))
            ++collapses;
    }
    return collapses;
}

SurfaceOptimiser::StarRatio SurfaceOptimiser::star_ratio(const UvMesh& mesh, index_t v, const Vec3& at) const {
    // The size ratios across the edges of v's fan: between consecutive fan triangles and
    // between each fan triangle and its neighbour across the rim.
    const auto& x = mesh.xyz;
    const std::size_t n = ring_.size();
    StarRatio r;
    const auto add = [&r](double s, double t) {
        const double ratio = std::max(s, t) / std::min(s, t);
        r.worst = std::max(r.worst, ratio);
        const double excess = std::log(ratio / kGradingRatio);
        if (excess > 0) r.penalty += excess * excess;
    };
    double first = 0, previous = 0;
    for (std::size_t j = 0; j < n; ++j) {
        if (mesh.node[ring_[j]] == mesh.node[ring_[(j + 1) % n]]) return {kUnknownRatio, kUnknownRatio};  // next to a pole
        const double s = mean_edge(at, x[ring_[j]], x[ring_[(j + 1) % n]]);
        if (j == 0) first = s;
        else add(s, previous);
        previous = s;
        const int k = mesh.local_index(fan_[j], v);
        const index_t o = mesh.neighbor(fan_[j], k);
        if (o != kNoIndex && !mesh.constrained(fan_[j], k) && mesh.inside(o) && size_[o] > 0) add(s, size_[o]);
    }
    add(first, previous);
    return r;
}

// Moves v part of the way (1, 3/4, 1/2, 1/4 or 1/8: small steps get past angle limits that
// a full one breaks) towards the apex of the equilateral triangle on edge a-b (on v's side)
// or, with a == kNoIndex, towards its neighbours' centroid, when that lowers the size ratios
// around v (StarRatio) without an angle of its fan dropping below 30 degrees (or its worst).
bool SurfaceOptimiser::try_grade(const SurfaceMap& surface, UvMesh& mesh, index_t v, index_t a, index_t b) {
    if (!gather_ring(mesh, v)) return false;
    const std::size_t n = ring_.size();
    const auto& x = mesh.xyz;
    const StarRatio before = star_ratio(mesh, v, x[v]);
    const double angle_floor = std::max(fan_worst(), kGradingCosine);
    const SurfaceDerivatives d = surface.derivatives(mesh.uv[v]);
    Vec3 goal{0, 0, 0};
    if (a == kNoIndex) {
        for (index_t r : ring_) goal = {goal.x + x[r].x / n, goal.y + x[r].y / n, goal.z + x[r].z / n};
    } else {
        const Vec3 e = x[b] - x[a], mid{0.5 * (x[a].x + x[b].x), 0.5 * (x[a].y + x[b].y), 0.5 * (x[a].z + x[b].z)};
        Vec3 side = cross(cross(d.du, d.dv), e);
        if (dot(side, x[v] - mid) < 0) side = {-side.x, -side.y, -side.z};
        const double len_side = std::sqrt(dot(side, side));
        if (!(len_side > 0)) return false;
        const double s = 0.8660254037844386 * std::sqrt(dot(e, e)) / len_side;
        goal = {mid.x + s * side.x, mid.y + s * side.y, mid.z + s * side.z};
    }
    StarRatio best = before;
    Uv best_uv = mesh.uv[v];
    Vec3 best_x = x[v];
    for (const double w : {1.0, 0.75, 0.5, 0.25, 0.125}) {
        Uv step;
        const Vec3 target{x[v].x + w * (goal.x - x[v].x), x[v].y + w * (goal.y - x[v].y), x[v].z + w * (goal.z - x[v].z)};
        if (!tangent_step(d, target - x[v], step)) continue;
        const Uv uv{mesh.uv[v].u + step.u, mesh.uv[v].v + step.v};
        bool valid = true;
        for (std::size_t j = 0; j < n && valid; ++j)
            valid = orient2d(uv, mesh.uv[ring_[j]], mesh.uv[ring_[(j + 1) % n]]) > 0;
        if (!valid) continue;
        const Vec3 moved = surface.point(uv);
        if (!fan_faces_out(mesh, v, moved)) continue;
        double worst = -1;
        for (std::size_t j = 0; j < n; ++j) worst = std::max(worst, fan_cosine(mesh, moved, j));
        if (worst > angle_floor) continue;
        // Better when the ratios above kGradingRatio shrink in sum (of squared logs) and the
        // worst does not grow: an excess can then be passed on to where it is smaller.
        const StarRatio ratio = star_ratio(mesh, v, moved);
        if (ratio.penalty < best.penalty && ratio.worst <= best.worst) best = ratio, best_uv = uv, best_x = moved;
    }
    if (best_uv.u == mesh.uv[v].u && best_uv.v == mesh.uv[v].v) return false;
    mesh.uv[v] = best_uv;
    mesh.xyz[v] = best_x;
    for (index_t t : fan_) update_quality(mesh, t);
    return true;
}

index_t SurfaceOptimiser::grading_sweep(const SurfaceMap& surface, index_t first_movable, UvMesh& mesh) {
    index_t moves = 0;
    for (index_t t = 0; t < mesh.slot_count(); ++t) {
        if (mesh.dead(t) || !mesh.inside(t)) continue;
        for (int i = 0; i < 3; ++i) {
            const index_t n = mesh.neighbor(t, i);
            if (mesh.constrained(t, i) || n == kNoIndex || n < t) continue;
            const double st = size_[t], sn = size_[n];
            if (std::max(st, sn) <= kGradingRatio * std::min(st, sn)) continue;
            // The big triangle's apex towards the shared edge, the small one's away from it, or
            // failing both (boundary vertices) an end of the shared edge towards its centroid.
            const index_t a = mesh.vertex(t, next3(i)), b = mesh.vertex(t, prev3(i));
            const index_t apex_t = mesh.vertex(t, i);
            const index_t apex_n = mesh.vertex(n, static_cast<int>(mesh.adj[3 * t + i] % 3));
            const index_t big = st > sn ? apex_t : apex_n, small = st > sn ? apex_n : apex_t;
            if ((big >= first_movable && try_grade(surface, mesh, big, a, b)) ||
                (small >= first_movable && try_grade(surface, mesh, small, a, b)) ||
                (a >= first_movable && try_grade(surface, mesh, a, kNoIndex, kNoIndex)) ||
                (b >= first_movable && try_grade(surface, mesh, b, kNoIndex, kNoIndex)))
                ++moves;
        }
    }
    return moves;
}

void SurfaceOptimiser::run(const SurfaceMap& surface, int passes, index_t first_movable, UvMesh& mesh,
                           FaceMeshStats& stats) {
    quality_.assign(mesh.slot_count(), -1.0);
    size_.assign(mesh.slot_count(), 0.0);
    for (index_t t = 0; t < mesh.slot_count(); ++t)
        if (!mesh.dead(t) && mesh.inside(t)) update_quality(mesh, t);
    stats.flips += flip_sweep(mesh);
    for (int pass = 0; pass < passes; ++pass) {
        const index_t moves = smooth_sweep(surface, first_movable, mesh);
        const index_t flips = flip_sweep(mesh);
        const index_t collapses = collapse_sweep(first_movable, mesh);
        stats.moves += moves;
        stats.flips += flips;
        stats.collapses += collapses;
        if (moves == 0 && flips == 0 && collapses == 0) break;
    }
    for (int pass = 0; pass < passes; ++pass) {
        const index_t moves = grading_sweep(surface, first_movable, mesh);
        stats.moves += moves;
        if (moves == 0) break;
    }
}

}  // namespace tubemesh::surface
