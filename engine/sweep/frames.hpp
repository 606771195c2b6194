#pragma once
// Rotation-minimising frames along a tube's centre line: the frames the sweep places its
// cross-sections in, so no twist builds up along bends and serpentine paths.
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "engine/core/vec3.hpp"

namespace tubemesh {

struct Frame {
    Vec3 tangent;   // unit, along the centre line
    Vec3 normal;    // unit, orthogonal to tangent; angle 0 of the cross-section
    Vec3 binormal; // tangent x normal; angle pi/2
};

// Double-reflection method (Wang, Jüttler, Zheng, Liu 2008): each frame is the previous one
// reflected twice, which approximates the rotation-minimising (Bishop) frame to fourth order
// per step. `initial_normal` is projected onto the plane normal to the first tangent.
// Throws tubemesh::Error for fewer than two stations, zero tangents, repeated stations or an
// initial normal parallel to the first tangent.
std::vector<Frame> rotation_minimizing_frames(std::span<const Vec3> centres, std::span<const Vec3> tangents,
                                              const Vec3& initial_normal);

// A unit vector orthogonal to `t`, chosen by a fixed rule so callers without a preferred
// direction get a reproducible one.
Vec3 any_orthogonal(const Vec3& t);

// Signed angle from a to b around the unit axis (both projected onto the plane normal to it).
double signed_angle(const Vec3& a, const Vec3& b, const Vec3& axis);

// The angle equal to a modulo 2π in (-π, π].
inline double wrap_angle(double a) {
    constexpr double two_pi = 2 * std::numbers::pi;
    a = std::remainder(a, two_pi);
    return a <= -std::numbers::pi ? a + two_pi : a;
}

}  // namespace tubemesh
