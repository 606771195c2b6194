#include "engine/sweep/tube_plan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/sweep/frames.hpp"
#include "engine/sweep/ring_dimensions.hpp"
#include "engine/sweep/ring_room.hpp"
#include "engine/sweep/stop_plane.hpp"

namespace tubemesh::sweep {
namespace {

// An end's depths fade over this many times their largest magnitude: every axial edge then
// stays within [1/2, 3/2] of the step.
constexpr double kBlendOverDepth = 2.0;
// ... and over at least this many steps, so the end's uneven angular spacing turns into the
// even one gradually.
constexpr double kMinBlendSteps = 2.0;
// Shortest axial edge, over the step, that the fading may leave when a short tube's two blends
// have to share its length.
constexpr double kMinAxialShrink = 0.2;

const SurfaceMap* surface_of(const SurfaceLookup& surfaces, index_t face, const char* role) {
    const SurfaceMap* s = surfaces ? surfaces(face) : nullptr;
    if (!s) throw Error(std::string(role) + " face " + std::to_string(face) + " has no surface map");
    return s;
}

double tube_sweep_size(index_t index, const SweepOptions& options, double radius) {
    double st = options.sweep_size;
    if (index < options.tube_sweep_size.size() && options.tube_sweep_size[index] > 0) st = options.tube_sweep_size[index];
    if (st == 0) st = 2 * radius;
    if (!(st > 0) || !std::isfinite(st)) throw Error("the sweep size St (" + std::to_string(st) + ") is not positive");
    return st;
}

void check_options(const SweepOptions& o) {
    if (o.radial_layers < 1) throw Error("sweep: radial_layers must be at least 1");
    if (!(o.grading > 0) || !std::isfinite(o.grading)) throw Error("sweep: grading must be positive");
    if (!(o.axial_aspect > 0) || !std::isfinite(o.axial_aspect)) throw Error("sweep: axial_aspect must be positive");
}

// Shortest axial edge over its station spacing, over all nodes: how much the end depths'
// fading shrinks the hexes next to the ends.
double min_axial_ratio(const TubePlan& p) {
    const auto& st = p.line.stations;
    const std::size_t nodes = p.ends[0].depth.size();
    double worst = 1.0;
    for (std::size_t i = 0; i + 1 < st.size(); ++i) {
        const double ds = st[i + 1].s - st[i].s;
        const double w0a = p.weight(0, st[i].s), w0b = p.weight(0, st[i + 1].s);
        const double w1a = p.weight(1, st[i].s), w1b = p.weight(1, st[i + 1].s);
        for (std::size_t q = 0; q < nodes; ++q) {
            const double moved = (w0b - w0a) * p.ends[0].depth[q] + (w1b - w1a) * p.ends[1].depth[q];
            worst = std::min(worst, (ds + moved) / ds);
        }
    }
    return worst;
}

}  // namespace

double TubePlan::weight(int e, double s) const {
    const double from_end = e == 0 ? s : line.length - s;
    return std::max(0.0, 1.0 - from_end / blend[static_cast<std::size_t>(e)]);
}

double TubePlan::angle(int k, double s) const {
    const std::size_t kk = static_cast<std::size_t>(k);
    return base[kk] + twist * (s / line.length) + weight(0, s) * angle_offset[0][kk] + weight(1, s) * angle_offset[1][kk];
}

double TubePlan::scale(double s, const Vec3& dir) const {
    return thin ? room_scale(*room, sweep_size, s, dir) : 1.0;
}

TubePlan plan_tube(const TubeData& tube, index_t index, const SurfaceLookup& surfaces, const SweepOptions& options) {
    check_options(options);
    if (tube.stations.size() < 2) throw Error("its centre line has fewer than two stations");
    if (tube.ring1.size() != tube.ring2.size())
        throw Error("its end rings have " + std::to_string(tube.ring1.size()) + " and " +
                    std::to_string(tube.ring2.size()) + " nodes; they must have the same number");
    if (tube.ring1.size() < 4) throw Error("its end rings have fewer than 4 nodes");

    TubePlan p;
    p.tube = index;
    p.n = static_cast<int>(tube.ring1.size());
    p.layers = options.radial_layers;
    for (int e = 0; e < 2; ++e) {
        const std::size_t ee = static_cast<std::size_t>(e);
        if (tube.stops[ee]) {
            const TubeStation& s = e == 0 ? tube.stations.front() : tube.stations.back();
            p.stop_planes[ee] = stop_plane(s.centre, s.tangent, e == 1, s.radius);
            p.hosts[ee] = p.stop_planes[ee].get();
        } else {
            p.hosts[ee] = surface_of(surfaces, e == 0 ? tube.host1 : tube.host2, "host");
        }
    }
    if (tube.wall_faces.empty()) throw Error("it has no wall faces");
    std::vector<const SurfaceMap*> walls;
    for (index_t f : tube.wall_faces) walls.push_back(surface_of(surfaces, f, "wall"));

    for (const TubeStation& s : tube.stations) p.radius += s.radius;
    p.radius /= static_cast<double>(tube.stations.size());
    if (!(p.radius > 0) || !std::isfinite(p.radius)) throw Error("its radius is not positive");
    p.wall = WallProjection(std::move(walls), p.radius);
    const std::vector<Vec3> ring1 = snap_to_wall_and_host(tube.ring1, p.wall, *p.hosts[0], p.radius, "ring1");
    const std::vector<Vec3> ring2 = snap_to_wall_and_host(tube.ring2, p.wall, *p.hosts[1], p.radius, "ring2");
    p.sweep_size = tube_sweep_size(index, options, p.radius);
    p.offsets = radial_offsets(p.sweep_size, p.layers, options.grading);
    p.step = axial_step(p.radius, p.offsets, p.n, options.axial_aspect, options.max_condition);
    p.room = &tube.room;
    p.thin = thinnest(tube.room) < p.sweep_size;
    if (p.thin) {
        // Where the ring is thin its outer quads are narrow and the gap ahead is thin: the step
        // follows the narrowest outer side there (no condition cap: a thin ring's hexes are
        // set by their thin layer, which a shorter step does not mend), never longer than St's.
        const double sine = std::sin(std::numbers::pi / p.n);
        const auto local = [&p, &tube, sine, aspect = options.axial_aspect](double s) {
            const double t = std::min(p.sweep_size, thinnest_at(tube.room, s));
            return std::min(p.step, aspect * 2 * (p.radius + t) * sine);
        };
        p.line = resample_centre_line(tube.stations, p.step, ring1.front(), local);
    } else {
        p.line = resample_centre_line(tube.stations, p.step, ring1.front());
    }

    const Station& first = p.line.stations.front();
    const Station& last = p.line.stations.back();
    p.ends = {ring_section(ring1, first), ring_section(ring2, last)};
    p.turn = ring_turn(p.ends[0], "ring1");
    if (ring_turn(p.ends[1], "ring2") != p.turn)
        throw Error("its end rings turn opposite ways about the centre line; they must turn the same way");

    // Even spacing from ring1's node 0; what is left at each end fades out near it.
    const double even = 2 * std::numbers::pi / p.n;
    p.twist = wrap_angle(p.ends[1].angle[0] - p.ends[0].angle[0]);
    for (int k = 0; k < p.n; ++k) {
        const std::size_t kk = static_cast<std::size_t>(k);
        p.base.push_back(p.ends[0].angle[0] + p.turn * even * k);
        p.angle_offset[0].push_back(wrap_angle(p.ends[0].angle[kk] - p.base[kk]));
        p.angle_offset[1].push_back(wrap_angle(p.ends[1].angle[kk] - p.base[kk] - p.twist));
    }

    for (int e = 0; e < 2; ++e) {
        const Station& st = e == 0 ? first : last;
        const EndSection& end = p.ends[static_cast<std::size_t>(e)];
        const Vec3 binormal = cross(st.tangent, st.reference);
        for (int k = 0; k < p.n; ++k) {
            const double a = end.angle[static_cast<std::size_t>(k)];
            p.end_scale[static_cast<std::size_t>(e)].push_back(
                p.scale(st.s, std::cos(a) * st.reference + std::sin(a) * binormal));
        }
    }
    const double scale = p.radius + p.sweep_size;
    place_on_host(p.ends[0], first, *p.hosts[0], p.offsets, scale, p.end_scale[0]);
    place_on_host(p.ends[1], last, *p.hosts[1], p.offsets, scale, p.end_scale[1]);

    const double spacing = p.line.length / (p.stations() - 1);
    for (int e = 0; e < 2; ++e) {
        double deepest = 0;
        for (double d : p.ends[static_cast<std::size_t>(e)].depth) deepest = std::max(deepest, std::abs(d));
        p.blend[static_cast<std::size_t>(e)] = std::max(kBlendOverDepth * deepest, kMinBlendSteps * spacing);
    }
    // A short tube: both ends fade over the whole length, in proportion.
    if (p.blend[0] + p.blend[1] > p.line.length) {
        const double shrink = p.line.length / (p.blend[0] + p.blend[1]);
        p.blend[0] *= shrink;
        p.blend[1] *= shrink;
    }
    if (min_axial_ratio(p) < kMinAxialShrink)
        throw Error("its ends are too oblique for its length: the ring of thickness St = " +
                    std::to_string(p.sweep_size) + " reaches " + std::to_string(p.blend[0] / kBlendOverDepth) +
                    " and " + std::to_string(p.blend[1] / kBlendOverDepth) + " along the axis at its ends, " +
                    "the tube is " + std::to_string(p.line.length) + " long; lower St");
    return p;
}

}  // namespace tubemesh::sweep
