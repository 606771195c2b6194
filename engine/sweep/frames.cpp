#include "engine/sweep/frames.hpp"

#include <cmath>
#include <string>

#include "engine/core/types.hpp"

namespace tubemesh {

namespace {

Eigen::Vector3d unit(const Eigen::Vector3d& v, const char* what, std::size_t i) {
    const double n = v.norm();
    if (!(n > 0.0) || !std::isfinite(n))
        throw Error(std::string("rotation-minimising frames: ") + what + " " + std::to_string(i) + " has zero length");
    return v / n;
}

// Reflection of v in the plane through the origin with normal w (w·w = c, c > 0).
Eigen::Vector3d reflect(const Eigen::Vector3d& v, const Eigen::Vector3d& w, double c) {
    return v - (2.0 / c) * w.dot(v) * w;
}

}  // namespace

Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& t) {
    // Cross with the coordinate axis least aligned with t: never near-parallel.
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    if (std::abs(t.y()) < std::abs(t.x()) && std::abs(t.y()) <= std::abs(t.z()))
        axis = Eigen::Vector3d::UnitY();
    else if (std::abs(t.z()) < std::abs(t.x()) && std::abs(t.z()) < std::abs(t.y()))
        axis = Eigen::Vector3d::UnitZ();
    return t.cross(axis).normalized();
}

double signed_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& axis) {
    const Eigen::Vector3d pa = a - axis.dot(a) * axis, pb = b - axis.dot(b) * axis;
    return std::atan2(axis.dot(pa.cross(pb)), pa.dot(pb));
}

std::vector<Frame> rotation_minimizing_frames(std::span<const Eigen::Vector3d> centres,
                                              std::span<const Eigen::Vector3d> tangents,
                                              const Eigen::Vector3d& initial_normal) {
    if (centres.size() < 2 || tangents.size() != centres.size())
        throw Error("rotation-minimising frames: need at least two stations with one tangent each");
    std::vector<Frame> frames(centres.size());
    Eigen::Vector3d t = unit(tangents[0], "tangent", 0);
    Eigen::Vector3d r = initial_normal - t.dot(initial_normal) * t;
    if (!(r.norm() > 1e-12 * initial_normal.norm()))
        throw Error("rotation-minimising frames: the initial normal is parallel to the first tangent");
    r.normalize();
    frames[0] = {t, r, t.cross(r)};
    for (std::size_t i = 0; i + 1 < centres.size(); ++i) {
        const Eigen::Vector3d v1 = centres[i + 1] - centres[i];
        const double c1 = v1.squaredNorm();
        if (!(c1 > 0.0)) throw Error("rotation-minimising frames: stations " + std::to_string(i) + " and " +
                                     std::to_string(i + 1) + " coincide");
        const Eigen::Vector3d t_next = unit(tangents[i + 1], "tangent", i + 1);
        // First reflection maps station i onto station i+1; the second aligns the tangents.
        const Eigen::Vector3d r_l = reflect(r, v1, c1);
        const Eigen::Vector3d t_l = reflect(t, v1, c1);
        const Eigen::Vector3d v2 = t_next - t_l;
        const double c2 = v2.squaredNorm();
        Eigen::Vector3d r_next = c2 > 1e-30 ? reflect(r_l, v2, c2) : r_l;
        // Re-orthonormalise so rounding does not accumulate over thousands of stations.
        r_next -= t_next.dot(r_next) * t_next;
        r_next.normalize();
        frames[i + 1] = {t_next, r_next, t_next.cross(r_next)};
        t = t_next;
        r = r_next;
    }
    return frames;
}

}  // namespace tubemesh
