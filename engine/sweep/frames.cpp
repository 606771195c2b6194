#include "engine/sweep/frames.hpp"

#include <cmath>
#include <string>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh {

namespace {

Vec3 unit(const Vec3& v, const char* what, std::size_t i) {
    const double n = norm(v);
    if (!(n > 0.0) || !std::isfinite(n))
        throw Error(std::string("rotation-minimising frames: ") + what + " " + std::to_string(i) + " has zero length");
    return v / n;
}

// Reflection of v in the plane through the origin with normal w (w·w = c, c > 0).
Vec3 reflect(const Vec3& v, const Vec3& w, double c) {
    return v - (2.0 / c) * dot(w, v) * w;
}

}  // namespace

Vec3 any_orthogonal(const Vec3& t) {
    // Cross with the coordinate axis least aligned with t: never near-parallel.
    Vec3 axis{1, 0, 0};
    if (std::abs(t.y) < std::abs(t.x) && std::abs(t.y) <= std::abs(t.z))
        axis = {0, 1, 0};
    else if (std::abs(t.z) < std::abs(t.x) && std::abs(t.z) < std::abs(t.y))
        axis = {0, 0, 1};
    return normalized(cross(t, axis));
}

double signed_angle(const Vec3& a, const Vec3& b, const Vec3& axis) {
    const Vec3 pa = a - dot(axis, a) * axis, pb = b - dot(axis, b) * axis;
    return std::atan2(dot(axis, cross(pa, pb)), dot(pa, pb));
}

std::vector<Frame> rotation_minimizing_frames(std::span<const Vec3> centres, std::span<const Vec3> tangents,
                                              const Vec3& initial_normal) {
    if (centres.size() < 2 || tangents.size() != centres.size())
        throw Error("rotation-minimising frames: need at least two stations with one tangent each");
    std::vector<Frame> frames(centres.size());
    Vec3 t = unit(tangents[0], "tangent", 0);
    Vec3 r = initial_normal - dot(t, initial_normal) * t;
    if (!(norm(r) > 1e-12 * norm(initial_normal)))
        throw Error("rotation-minimising frames: the initial normal is parallel to the first tangent");
    r = normalized(r);
    frames[0] = {t, r, cross(t, r)};
    for (std::size_t i = 0; i + 1 < centres.size(); ++i) {
        const Vec3 v1 = centres[i + 1] - centres[i];
        const double c1 = norm2(v1);
        if (!(c1 > 0.0)) throw Error("rotation-minimising frames: stations " + std::to_string(i) + " and " +
                                     std::to_string(i + 1) + " coincide");
        const Vec3 t_next = unit(tangents[i + 1], "tangent", i + 1);
        // First reflection maps station i onto station i+1; the second aligns the tangents.
        const Vec3 r_l = reflect(r, v1, c1);
        const Vec3 t_l = reflect(t, v1, c1);
        const Vec3 v2 = t_next - t_l;
        const double c2 = norm2(v2);
        Vec3 r_next = c2 > 1e-30 ? reflect(r_l, v2, c2) : r_l;
        // Re-orthonormalise so rounding does not accumulate over thousands of stations.
        r_next -= dot(t_next, r_next) * t_next;
        r_next = normalized(r_next);
        frames[i + 1] = {t_next, r_next, cross(t_next, r_next)};
        t = t_next;
        r = r_next;
    }
    return frames;
}

}  // namespace tubemesh
