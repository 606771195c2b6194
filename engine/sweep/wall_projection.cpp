#include "engine/sweep/wall_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh::sweep {
namespace {

// A foot point this little outside a face's range (relative to the range) is still on it:
// the point where two wall faces meet belongs to both.
constexpr double kRangeTolerance = 1e-6;
// Grid of points per parameter direction for a face's bounding box.
constexpr int kBoxSamples = 9;
// A foot point closer than this times the radius is taken without looking at other faces.
// The interpolated centre line puts raw points within about 0.003 r of the wall on the
// tests' tubes, so a correct foot passes easily; a face whose projection clamps to its
// boundary (a bounded B-spline) gives a foot at its end that is farther off by the overshoot,
// and fails unless that is negligible.
constexpr double kTrustedDistance = 0.05;

bool within(const ParamRange& r, double t) {
    if (r.closed) return true;
    const double tol = kRangeTolerance * (r.hi - r.lo);
    return t >= r.lo - tol && t <= r.hi + tol;
}

bool on_face(const SurfaceMap& s, Uv uv) { return within(s.u_range(), uv.u) && within(s.v_range(), uv.v); }

double box_distance(const Vec3& lo, const Vec3& hi, const Vec3& p) {
    return norm(min_each(max_each(p, lo), hi) - p);
}

}  // namespace

WallProjection::WallProjection(std::vector<const SurfaceMap*> faces, double radius)
    : faces_(std::move(faces)), radius_(radius) {
    for (const SurfaceMap* s : faces_) {
        const ParamRange u = s->u_range(), v = s->v_range();
        constexpr double inf = std::numeric_limits<double>::infinity();
        Box b{{inf, inf, inf}, {-inf, -inf, -inf}};
        for (int i = 0; i < kBoxSamples; ++i)
            for (int j = 0; j < kBoxSamples; ++j) {
                const double fu = static_cast<double>(i) / (kBoxSamples - 1), fv = static_cast<double>(j) / (kBoxSamples - 1);
                const Vec3 p = s->point({u.lo + fu * (u.hi - u.lo), v.lo + fv * (v.hi - v.lo)});
                b.lo = min_each(b.lo, p);
                b.hi = max_each(b.hi, p);
            }
        boxes_.push_back(b);
    }
}

std::optional<Projection> WallProjection::try_face(int f, const Vec3& p, std::optional<Uv> hint) const {
    const Projection pr = faces_[static_cast<std::size_t>(f)]->project(p, hint);
    if (!pr.ok || !std::isfinite(pr.distance)) return std::nullopt;
    return pr;
}

bool WallProjection::acceptable(int f, const Projection& pr) const {
    return pr.distance <= kTrustedDistance * radius_ && on_face(*faces_[static_cast<std::size_t>(f)], pr.uv);
}

WallFoot WallProjection::project(const Vec3& p, WallCursor& cursor) const {
    if (cursor.face >= 0) {
        if (auto pr = try_face(cursor.face, p, cursor.uv); pr && acceptable(cursor.face, *pr)) {
            cursor.uv = pr->uv;
            return {pr->point, pr->distance};
        }
    }
    std::vector<int> order(faces_.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> away(faces_.size());
    for (std::size_t f = 0; f < faces_.size(); ++f) away[f] = box_distance(boxes_[f].lo, boxes_[f].hi, p);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return away[static_cast<std::size_t>(a)] < away[static_cast<std::size_t>(b)]; });

    int best = -1;
    bool best_on_face = false;
    std::optional<Projection> best_pr;
    for (int f : order) {
        const auto pr = try_face(f, p, f == cursor.face ? std::optional<Uv>(cursor.uv) : std::nullopt);
        if (!pr) continue;
        if (acceptable(f, *pr)) {
            best = f;
            best_pr = pr;
            break;
        }
        const bool inside = on_face(*faces_[static_cast<std::size_t>(f)], pr->uv);
        // A foot on its face beats one off its face; then the nearer wins (the first on a tie).
        if (!best_pr || (inside && !best_on_face) || (inside == best_on_face && pr->distance < best_pr->distance)) {
            best = f;
            best_on_face = inside;
            best_pr = pr;
        }
    }
    if (!best_pr || !(best_pr->distance <= 0.5 * radius_))
        throw Error("a wall node at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                    std::to_string(p.z) + ") has no foot point on the tube's wall within half its radius: " +
                    "the centre line does not follow the wall");
    cursor = {best, best_pr->uv};
    return {best_pr->point, best_pr->distance};
}

Vec3 WallProjection::normal(const WallCursor& cursor) const {
    if (cursor.face < 0 || static_cast<std::size_t>(cursor.face) >= faces_.size())
        throw Error("wall normal asked for before any foot point was found");
    const SurfaceMap& s = *faces_[static_cast<std::size_t>(cursor.face)];
    const Vec3 n = s.normal(cursor.uv);
    if (!(norm2(n) > 0.5))
        throw Error("the wall of face " + std::to_string(s.face()) + " has no normal at a foot point");
    return n;
}

}  // namespace tubemesh::sweep
