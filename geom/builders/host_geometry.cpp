#include "geom/builders/host_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tubemesh::geom {

Vec3 unit(const Vec3& a) { return (1.0 / norm(a)) * a; }

double host_volume(const HostSpec& host) {
    if (host.kind == HostSpec::Kind::Box) return host.size.x * host.size.y * host.size.z;
    const double r = host.diameter / 2;
    return std::numbers::pi * r * r * host.length;
}

double host_extent(const HostSpec& host) {
    if (host.kind == HostSpec::Kind::Box) return norm(host.size);
    return std::hypot(host.diameter, host.diameter, host.length);
}

double signed_boundary_distance(const HostSpec& host, const Vec3& p) {
    if (host.kind == HostSpec::Kind::Box) {
        const double lo[3] = {p.x, p.y, p.z};
        const double hi[3] = {host.size.x - p.x, host.size.y - p.y, host.size.z - p.z};
        double inside = lo[0];
        double outside2 = 0;
        for (int i = 0; i < 3; ++i) {
            inside = std::min({inside, lo[i], hi[i]});
            const double out = std::max({0.0, -lo[i], -hi[i]});
            outside2 += out * out;
        }
        return inside >= 0 ? inside : -std::sqrt(outside2);
    }
    const double radial = host.diameter / 2 - std::hypot(p.x, p.y);
    const double axial = std::min(p.z, host.length - p.z);
    if (radial >= 0 && axial >= 0) return std::min(radial, axial);
    return -std::hypot(std::max(0.0, -radial), std::max(0.0, -axial));
}

std::optional<Vec3> boundary_normal(const HostSpec& host, const Vec3& p, double tol) {
    if (host.kind == HostSpec::Kind::Box) {
        if (std::abs(p.x) <= tol) return Vec3{-1, 0, 0};
        if (std::abs(p.x - host.size.x) <= tol) return Vec3{1, 0, 0};
        if (std::abs(p.y) <= tol) return Vec3{0, -1, 0};
        if (std::abs(p.y - host.size.y) <= tol) return Vec3{0, 1, 0};
        if (std::abs(p.z) <= tol) return Vec3{0, 0, -1};
        if (std::abs(p.z - host.size.z) <= tol) return Vec3{0, 0, 1};
        return std::nullopt;
    }
    const double rho = std::hypot(p.x, p.y);
    if (std::abs(rho - host.diameter / 2) <= tol && rho > 0) return Vec3{p.x / rho, p.y / rho, 0};
    if (std::abs(p.z) <= tol) return Vec3{0, 0, -1};
    if (std::abs(p.z - host.length) <= tol) return Vec3{0, 0, 1};
    return std::nullopt;
}

}  // namespace tubemesh::geom
