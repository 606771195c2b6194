#include "engine/sweep/ring_ends.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/sweep/frames.hpp"

namespace tubemesh::sweep {
namespace {

// sin(6°): a host closer to parallel with the axis gives no usable end cross-section.
constexpr double kMinHostSine = 0.1;
constexpr int kMaxNewtonSteps = 50;

struct HostHit {
    Vec3 point;
    Uv uv;
    double depth;
};

// Where the line origin + d·t meets the host, by Newton steps on the signed distance from
// the surface starting at d = depth; each step projects onto the host (with the previous
// foot point's uv as hint) and moves along the line to the foot point's tangent plane.
HostHit hit_host(const SurfaceMap& host, const Vec3& origin, const Vec3& t, double depth, std::optional<Uv> hint,
                 double scale) {
    for (int step = 0; step < kMaxNewtonSteps; ++step) {
        const Projection pr = host.project(origin + depth * t, hint);
        if (!pr.ok) throw Error("no foot point on host face " + std::to_string(host.face()));
        const Vec3 normal = host.normal(pr.uv);
        const double across = dot(normal, t);
        if (!(std::abs(across) >= kMinHostSine))
            throw Error("host face " + std::to_string(host.face()) +
                        " is nearly parallel to the tube's axis where the ring meets it");
        const double move = dot(origin + depth * t - pr.point, normal) / across;
        depth -= move;
        hint = pr.uv;
        if (std::abs(move) <= 1e-13 * scale) break;
    }
    const Projection pr = host.project(origin + depth * t, hint);
    if (!pr.ok) throw Error("no foot point on host face " + std::to_string(host.face()));
    return {pr.point, pr.uv, depth};
}

// A node closer than this to both surfaces, over the radius, is on the curve: far below
// the 1e-7 r the rings are held to, above the rounding of coordinates of a large model.
constexpr double kSnapTolerance = 1e-11;
// Newton converges quadratically from a start this close: a few steps. The cap only stops a
// loop that rounding keeps from the tolerance; the node is then as close as it gets.
constexpr int kMaxSnapSteps = 10;
// geom's loop lies within its edge tolerance of both surfaces; a node this far off (over the
// radius) is on some other loop, or the surfaces are not the tube's.
constexpr double kMaxSnapMove = 0.05;
// 1 - cos² of the angle between the two surfaces below which they are taken as tangent.
constexpr double kMinCrossing = 1e-8;

Vec3 snap_node(const Vec3& start, const WallProjection& wall, WallCursor& cursor, const SurfaceMap& host,
               std::optional<Uv>& hint, double radius, const std::string& name) {
    Vec3 x = start;
    for (int step = 0;; ++step) {
        const WallFoot w = wall.project(x, cursor);
        const Projection h = host.project(x, hint);
        if (!h.ok) throw Error(name + " has no foot point on host face " + std::to_string(host.face()));
        hint = h.uv;
        if ((w.distance <= kSnapTolerance * radius && h.distance <= kSnapTolerance * radius) || step == kMaxSnapSteps)
            break;
        const Vec3 nw = wall.normal(cursor);
        const Vec3 nh = host.normal(h.uv);
        const double c = dot(nw, nh), crossing = 1 - c * c;
        if (!(crossing > kMinCrossing))
            throw Error(name + ": the wall and host face " + std::to_string(host.face()) + " meet tangentially there");
        // x - a·nw - b·nh on both tangent planes: a + c·b = dw, c·a + b = dh.
        const double dw = dot(nw, x - w.point), dh = dot(nh, x - h.point);
        x -= ((dw - c * dh) / crossing) * nw + ((dh - c * dw) / crossing) * nh;
    }
    if (!(norm(x - start) <= kMaxSnapMove * radius))
        throw Error(name + " lies " + std::to_string(norm(x - start) / radius) +
                    " radii from where the wall meets host face " + std::to_string(host.face()));
    return x;
}

}  // namespace

std::vector<Vec3> snap_to_wall_and_host(std::span<const Vec3> ring, const WallProjection& wall,
                                        const SurfaceMap& host, double radius, const char* which) {
    std::vector<Vec3> out;
    out.reserve(ring.size());
    // Each node starts from its predecessor's foot points: neighbours on a loop are close.
    WallCursor cursor;
    std::optional<Uv> hint;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::string name = std::string(which) + " node " + std::to_string(k);
        out.push_back(snap_node(ring[k], wall, cursor, host, hint, radius, name));
    }
    return out;
}

EndSection ring_section(std::span<const Vec3> ring, const Station& station) {
    EndSection e;
    for (const Vec3& p : ring) {
        const Vec3 d = p - station.centre;
        const double along = dot(d, station.tangent);
        e.node.push_back(p);
        e.uv.push_back({});
        e.depth.push_back(along);
        e.angle.push_back(signed_angle(station.reference, d, station.tangent));
        e.radius.push_back(norm(d - along * station.tangent));
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
                   std::span<const double> offsets, double scale, std::span<const double> node_scale) {
    const std::size_t n = section.angle.size();
    const std::size_t layers = offsets.size() - 1;
    section.node.resize((layers + 1) * n);
    section.uv.resize((layers + 1) * n);
    section.depth.resize((layers + 1) * n);
    const Vec3 binormal = cross(station.tangent, station.reference);
    for (std::size_t k = 0; k < n; ++k) {
        const Projection wall = host.project(section.node[k], std::nullopt);
        if (!wall.ok) throw Error("ring node " + std::to_string(k) + " has no foot point on host face " +
                                  std::to_string(host.face()));
        section.uv[k] = wall.uv;
        const double a = section.angle[k];
        const Vec3 dir = std::cos(a) * station.reference + std::sin(a) * binormal;
        std::optional<Uv> hint = wall.uv;
        double depth = section.depth[k];
        const double thin = k < node_scale.size() ? node_scale[k] : 1.0;
        for (std::size_t j = 1; j <= layers; ++j) {
            const double offset = thin < 1.0 ? thin * offsets[j] : offsets[j];
            const Vec3 origin = station.centre + (section.radius[k] + offset) * dir;
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
