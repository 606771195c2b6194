#include "engine/quality/standard_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/vec3_ops.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kDegreesPerRadian = 57.295779513082320876798154814105;

}  // namespace

double tet_scaled_jacobian(const std::array<Vec3, 4>& p) {
    const double ab = norm2(p[1] - p[0]), ac = norm2(p[2] - p[0]), ad = norm2(p[3] - p[0]);
    const double bc = norm2(p[2] - p[1]), bd = norm2(p[3] - p[1]), cd = norm2(p[3] - p[2]);
    const double largest = std::max({ab * ac * ad, ab * bc * bd, ac * bc * cd, ad * bd * cd});
    const double det = dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0]));
    const double lengths = std::max(std::sqrt(largest), std::abs(det));
    if (!(lengths > 0)) return 0.0;
    return std::sqrt(2.0) * det / lengths;
}

double tet_min_dihedral_degrees(const std::array<Vec3, 4>& p) {
    // Outward face normals (unnormalised): the dihedral angle at an edge is pi minus the angle
    // between the outward normals of the two faces that meet there.
    const Vec3 n0 = cross(p[2] - p[1], p[3] - p[1]);  // face 1-2-3, opposite 0
    const Vec3 n1 = cross(p[3] - p[0], p[2] - p[0]);  // face 0-3-2
    const Vec3 n2 = cross(p[1] - p[0], p[3] - p[0]);  // face 0-1-3
    const Vec3 n3 = cross(p[2] - p[0], p[1] - p[0]);  // face 0-2-1
    const std::array<Vec3, 4> n{n0, n1, n2, n3};
    // acos(-c) rises with c (and acos is correctly rounded, so monotone in doubles too): the
    // smallest angle is that of the smallest cosine, one acos instead of six.
    double smallest = kInfinity;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            const double lengths = std::sqrt(norm2(n[i]) * norm2(n[j]));
            if (!(lengths > 0)) return 0.0;
            smallest = std::min(smallest, std::clamp(dot(n[i], n[j]) / lengths, -1.0, 1.0));
        }
    // No pair with a cosine (all NaN): the angle stays unknown, as infinity.
    if (!(smallest < kInfinity)) return kInfinity;
    return std::acos(-smallest) * kDegreesPerRadian;
}

double tet_aspect_ratio(const std::array<Vec3, 4>& p) {
    const Vec3 ab = p[1] - p[0], ac = p[2] - p[0], ad = p[3] - p[0];
    const Vec3 bc = p[2] - p[1], bd = p[3] - p[1], cd = p[3] - p[2];
    const double det = dot(ab, cross(ac, ad));
    if (!(det > 0)) return kInfinity;
    const double longest =
        std::sqrt(std::max({norm2(ab), norm2(ac), norm2(ad), norm2(bc), norm2(bd), norm2(cd)}));
    // Twice the four face areas.
    const double areas2 = norm(cross(ab, bc)) + norm(cross(ab, ad)) + norm(cross(ac, ad)) + norm(cross(bc, cd));
    return std::sqrt(6.0) / 12.0 * longest * areas2 / det;
}

double hex_centre_scaled_jacobian(const std::array<Vec3, 8>& p) {
    // Principal axes: right face minus left, back minus front, top minus bottom (sums of four).
    auto sum4 = [&](int a, int b, int c, int d) { return p[a] + p[b] + p[c] + p[d]; };
    const Vec3 xi = sum4(1, 2, 5, 6) - sum4(0, 3, 4, 7);
    const Vec3 eta = sum4(2, 3, 6, 7) - sum4(0, 1, 4, 5);
    const Vec3 zeta = sum4(4, 5, 6, 7) - sum4(0, 1, 2, 3);
    const double lengths = std::sqrt(norm2(xi) * norm2(eta) * norm2(zeta));
    return lengths > 0 ? dot(xi, cross(eta, zeta)) / lengths : 0.0;
}

double hex_verdict_scaled_jacobian(const std::array<Vec3, 8>& p) {
    return std::min(hex_centre_scaled_jacobian(p), hex_quality(p).scaled_jacobian);
}

}  // namespace tubemesh
