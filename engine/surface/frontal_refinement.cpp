#include "engine/surface/frontal_refinement.hpp"
#include "engine/core/vec3_ops.hpp"

#include <algorithm>
#include <cmath>

namespace tubemesh::surface {

namespace {

constexpr double kSqrt3 = 1.7320508075688772;
constexpr double kUnbounded = 1e30;  // ratio of a flat triangle: first in line, never accepted


bool before(const auto& x, const auto& y) {  // max-heap on ratio, ties by slot: deterministic
    return x.ratio < y.ratio || (x.ratio == y.ratio && x.triangle > y.triangle);
}

}  // namespace

namespace {

// At a pole or a cone's apex one parameter direction has zero length: the metric there says
// nothing about distances, and several uv vertices are one point.
bool singular(const Metric2& m) { return m.a * m.c - m.b * m.b <= 1e-8 * (m.a + m.c) * (m.a + m.c); }

}  // namespace

double FrontalRefiner::radius_ratio(const UvMesh& mesh, index_t t) const {
    const index_t a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
    const double h = (mesh.size[a] + mesh.size[b] + mesh.size[c]) / 3;
    const Vec3 ab = mesh.xyz[b] - mesh.xyz[a], bc = mesh.xyz[c] - mesh.xyz[b], ca = mesh.xyz[a] - mesh.xyz[c];
    const bool at_pole = singular(mesh.metric[a]) || singular(mesh.metric[b]) || singular(mesh.metric[c]);
    const bool repeated = mesh.node[a] == mesh.node[b] || mesh.node[b] == mesh.node[c] || mesh.node[c] == mesh.node[a];
    // Next to a pole, space is the only measure: a triangle on a pole's degenerate edge is a
    // segment in space, judged by its longest edge (1 for the ideal triangle too).
    if (at_pole && repeated) return std::max({norm(ab), norm(bc), norm(ca)}) / h;
    // Folded over in space (spanning a pole or a seam the wrong way round): never acceptable.
    if (!mesh.faces_out(a, b, c, mesh.xyz[a], mesh.xyz[b], mesh.xyz[c])) return kUnbounded;
    const double twice_area = norm(cross(ab, ca));
    const double in_space = twice_area > 1e-300 ? norm(ab) * norm(bc) * norm(ca) / (2 * twice_area) : kUnbounded;
    if (at_pole) return in_space * kSqrt3 / h;
    // Elsewhere also lengths in the mean of the corners' metrics: they see how far apart the
    // corners are in the face, where chords in space do not (the two sides of a seam are one
    // point in space; a big triangle on a curved face has short chords).
    const Metric2 &ma = mesh.metric[a], &mb = mesh.metric[b], &mc = mesh.metric[c];
    const Metric2 m{(ma.a + mb.a + mc.a) / 3, (ma.b + mb.b + mc.b) / 3, (ma.c + mb.c + mc.c) / 3};
    const auto metric_length = [&](index_t p, index_t q) {
        const double du = mesh.uv[q].u - mesh.uv[p].u, dv = mesh.uv[q].v - mesh.uv[p].v;
        return std::sqrt(std::max(0.0, m.a * du * du + 2 * m.b * du * dv + m.c * dv * dv));
    };
    const double mab = metric_length(a, b), mbc = metric_length(b, c), mca = metric_length(c, a);
    if (repeated) return std::max({mab, mbc, mca}) / h;  // across a seam
    const double du1 = mesh.uv[b].u - mesh.uv[a].u, dv1 = mesh.uv[b].v - mesh.uv[a].v;
    const double du2 = mesh.uv[c].u - mesh.uv[a].u, dv2 = mesh.uv[c].v - mesh.uv[a].v;
    const double twice_metric_area = std::abs(du1 * dv2 - dv1 * du2) * std::sqrt(std::max(0.0, m.a * m.c - m.b * m.b));
    const double in_metric = twice_metric_area > 1e-300 ? mab * mbc * mca / (2 * twice_metric_area) : kUnbounded;
    return std::max(in_space, in_metric) * kSqrt3 / h;
}

// The shortest edge the triangle shares with the finished region (or the boundary): building
// the ideal triangle on it fills the corners between fronts first, which leaves fewer gaps
// for fronts to collide in than the first or the longest edge did in the tests.
int FrontalRefiner::front_edge(const UvMesh& mesh, index_t t) const {
    int best = -1;
    double best_len = 0;
    for (int i = 0; i < 3; ++i) {
        const index_t n = mesh.neighbor(t, i);
        if (!mesh.constrained(t, i) && !(n != kNoIndex && mesh.inside(n) && mesh.accepted(n))) continue;
        const double len = norm((mesh.xyz[mesh.vertex(t, next3(i))] - mesh.xyz[mesh.vertex(t, prev3(i))]));
        if (best < 0 || len < best_len) best = i, best_len = len;
    }
    return best;
}

void FrontalRefiner::push_if_front(const UvMesh& mesh, index_t t) {
    if (t == kNoIndex || mesh.dead(t) || !mesh.inside(t) || mesh.accepted(t) || front_edge(mesh, t) < 0) return;
    heap_.push_back({ratio_[t], t, mesh.gen[t]});
    std::push_heap(heap_.begin(), heap_.end(), [](const Entry& x, const Entry& y) { return before(x, y); });
}

void FrontalRefiner::accept(UvMesh& mesh, index_t t) {
    mesh.flags[t] |= kAccepted;
    for (int i = 0; i < 3; ++i)
        if (!mesh.constrained(t, i)) push_if_front(mesh, mesh.neighbor(t, i));
}

void FrontalRefiner::settle(UvMesh& mesh, index_t t, double accept_ratio) {
    ratio_[t] = radius_ratio(mesh, t);
    if (ratio_[t] <= accept_ratio) mesh.flags[t] |= kAccepted;
}

bool FrontalRefiner::place_point(const SurfaceMap& surface, const UvMesh& mesh, index_t t, int edge, Uv& p) const {
    const index_t c = mesh.vertex(t, edge), a = mesh.vertex(t, next3(edge)), b = mesh.vertex(t, prev3(edge));
    const Uv ua = mesh.uv[a], ub = mesh.uv[b], uc = mesh.uv[c];
    const Uv m{0.5 * (ua.u + ub.u), 0.5 * (ua.v + ub.v)};
    // Work in the plane the metric at the midpoint makes Euclidean, origin at the midpoint.
    const MetricFactor f(surface_metric(surface.derivatives(m)));
    const Uv A = f.apply(ua.u - m.u, ua.v - m.v), C = f.apply(uc.u - m.u, uc.v - m.v);
    const double half = std::hypot(A.u, A.v);  // p in Rebay's notation; B = -A
    if (!(half > 0)) return false;
    const Uv n{A.v / half, -A.u / half};  // unit normal of a -> b, towards c
    const double nc = n.u * C.u + n.v * C.v;
    if (!(nc > 0)) return false;  // flat in the metric: no side to build on
    // The circumcentre is q·n (it lies on the bisector of a-b): |q n - A| = |q n - C|.
    const double q = ((C.u * C.u + C.v * C.v) - half * half) / (2 * nc);
    const double ideal = 0.5 * (mesh.size[a] + mesh.size[b]) / kSqrt3;  // circumradius of the ideal triangle
    double rho = std::max(ideal, half);
    // Not beyond the circumcentre: the circle through a, b and the circumcentre caps rho.
    if (q > 0) rho = std::min(rho, (half * half + q * q) / (2 * q));
    const double d = rho + std::sqrt(std::max(0.0, rho * rho - half * half));
    const Uv step = f.solve(d * n.u, d * n.v);
    p = {m.u + step.u, m.v + step.v};
    return std::isfinite(p.u) && std::isfinite(p.v);
}

void FrontalRefiner::run(const SurfaceMap& surface, const SizeField& size, const FaceMeshOptions& options,
                         index_t first_node, UvMesh& mesh, Inserter& inserter, FaceMeshStats& stats) {
    const auto cmp = [](const Entry& x, const Entry& y) { return before(x, y); };
    heap_.clear();
    ratio_.assign(mesh.slot_count(), 0.0);
    for (index_t t = 0; t < mesh.slot_count(); ++t)
        if (!mesh.dead(t) && mesh.inside(t)) settle(mesh, t, options.accept_ratio);
    for (index_t t = 0; t < mesh.slot_count(); ++t) push_if_front(mesh, t);

    index_t next_node = first_node;
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), cmp);
        const Entry top = heap_.back();
        heap_.pop_back();
        const index_t t = top.triangle;
        if (mesh.dead(t) || mesh.gen[t] != top.gen || mesh.accepted(t)) continue;
        const int edge = front_edge(mesh, t);
        if (edge < 0) continue;  // its front moved away; it is pushed again when one returns

        Uv p;
        if (!place_point(surface, mesh, t, edge, p)) {
            ++stats.points_refused;
            accept(mesh, t);
            continue;
        }
        const SurfaceDerivatives d = surface.derivatives(p);
        const double h = size.at(d.point);
        index_t v = kNoIndex;
        const InsertStatus s =
            inserter.insert(mesh, t, vertex_data(p, d, d.point, h, next_node), options.min_spacing * h, v);
        if (s != InsertStatus::Inserted) {
            ++stats.points_refused;
            accept(mesh, t);
            continue;
        }
        ++next_node;
        ++stats.points_inserted;
        ratio_.resize(mesh.slot_count());
        for (index_t c : inserter.created()) settle(mesh, c, options.accept_ratio);
        for (index_t c : inserter.created()) {
            if (mesh.accepted(c)) {
                for (int i = 0; i < 3; ++i)
                    if (!mesh.constrained(c, i)) push_if_front(mesh, mesh.neighbor(c, i));
            } else {
                push_if_front(mesh, c);
            }
        }
        // The point landed outside t's circle in its own metric: t stays and tries again (a
        // second point at the same place is refused, which then accepts t).
        if (!mesh.dead(t) && mesh.gen[t] == top.gen) push_if_front(mesh, t);
    }
}

}  // namespace tubemesh::surface
