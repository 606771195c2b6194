#pragma once
// Conversions between the mesh store's Vec3 and Eigen, and angle wrapping: the sweep computes
// in Eigen (as frames.hpp does) and stores Vec3.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cmath>
#include <numbers>

#include "engine/mesh/hybrid_mesh.hpp"  // Vec3

namespace tubemesh::sweep {

using V3 = Eigen::Vector3d;

inline V3 to_eigen(const Vec3& p) { return {p.x, p.y, p.z}; }
inline Vec3 to_vec3(const V3& p) { return {p.x(), p.y(), p.z()}; }

// The angle equal to a modulo 2π in (-π, π].
inline double wrap_angle(double a) {
    constexpr double two_pi = 2 * std::numbers::pi;
    a = std::remainder(a, two_pi);
    return a <= -std::numbers::pi ? a + two_pi : a;
}

}  // namespace tubemesh::sweep
