#include "engine/sweep/ring_ends.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/types.hpp"
#include "engine/sweep/frames.hpp"

namespace tubemesh::sweep {
namespace {

// sin(6°): a host closer to parallel with the axis gives no usable end cross-section.
constexpr double kMinHostSine = 0.1;
constexpr int kMaxNewtonSteps = 50;

struct HostHit {
    V3 point;
    Uv uv;
    double depth;
};

// Where the line origin + d·t meets the host, by Newton steps on the signed distance from
// the surface starting at d = depth; each step projects onto the host (with the previous
// foot point's uv as hint) and moves along the line to the foot point's tangent plane.
HostHit hit_host(const SurfaceMap& host, const V3& origin, const V3& t, double depth, std::optional<Uv> hint,
                 double scale) {
    for (int step = 0; step < kMaxNewtonSteps; ++step) {
        const Projection pr = host.project(to_vec3(origin + depth * t), hint);
        if (!pr.ok) throw Error("no foot point on host face " + std::to_string(host.face()));
        const V3 normal = to_eigen(host.normal(pr.uv));
        const double across = normal.dot(t);
        if (!(std::abs(across) >= kMinHostSine))
            throw Error("host face " + std::to_string(host.face()) +
                        " is nearly parallel to the tube's axis where the ring meets it");
        const double move = (origin + depth * t - to_eigen(pr.point)).dot(normal) / across;
        depth -= move;
        hint = pr.uv;
        if (std::abs(move) <= 1e-13 * scale) break;
    }
    const Projection pr = host.project(to_vec3(origin + depth * t), hint);
    if (!pr.ok) throw Error("no foot point on host face " + std::to_string(host.face()));
    return {to_eigen(pr.point), pr.uv, depth};
}

}  // namespace

EndSection ring_section(std::span<const Vec3> ring, const Station& station) {
    EndSection e;
    for (const Vec3& p : ring) {
        const V3 d = to_eigen(p) - station.centre;
        const double along = d.dot(station.tangent);
        e.node.push_back(to_eigen(p));
        e.uv.push_back({});
        e.depth.push_back(along);
        e.angle.push_back(signed_angle(station.reference, d, station.tangent));
        e.radius.push_back((d - along * station.tangent).norm());
    }
    return e;
}

int ring_turn(const EndSection& section, const char* which) {
    const std::size_t n = section.angle.size();
    double turned = 0;
    for (std::size_t k = 0; k < n; ++k) turned += wrap_angle(section.angle[(k + 1) % n] - section.angle[k]);
    // A ring that goes once around turns by ±2π; anything else is not a loop around the axis.
    if (!(std::abs(std::abs(turned) - 2 * std::numbers::pi) < 1e-6))
        throw Error(std::string(which) + " does not go once around the centre line");
    return turned > 0 ? 1 : -1;
}

void place_on_host(EndSection& section, const Station& station, const SurfaceMap& host,
                   std::span<const double> offsets, double scale) {
    const std::size_t n = section.angle.size();
    const std::size_t layers = offsets.size() - 1;
    section.node.resize((layers + 1) * n);
    section.uv.resize((layers + 1) * n);
    section.depth.resize((layers + 1) * n);
    const V3 binormal = station.tangent.cross(station.reference);
    for (std::size_t k = 0; k < n; ++k) {
        const Projection wall = host.project(to_vec3(section.node[k]), std::nullopt);
        if (!wall.ok) throw Error("ring node " + std::to_string(k) + " has no foot point on host face " +
                                  std::to_string(host.face()));
        section.uv[k] = wall.uv;
        const double a = section.angle[k];
        const V3 dir = std::cos(a) * station.reference + std::sin(a) * binormal;
        std::optional<Uv> hint = wall.uv;
        double depth = section.depth[k];
        for (std::size_t j = 1; j <= layers; ++j) {
            const V3 origin = station.centre + (section.radius[k] + offsets[j]) * dir;
            const HostHit hit = hit_host(host, origin, station.tangent, depth, hint, scale);
            section.node[j * n + k] = hit.point;
            section.uv[j * n + k] = hit.uv;
            section.depth[j * n + k] = hit.depth;
            hint = hit.uv;
            depth = hit.depth;
        }
    }
}

}  // namespace tubemesh::sweep
