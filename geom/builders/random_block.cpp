#include "geom/builders/random_block.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/types.hpp"
#include "geom/builders/centre_line.hpp"
#include "geom/builders/clearance.hpp"
#include "geom/builders/host_geometry.hpp"
#include "geom/builders/random.hpp"

namespace tubemesh::geom {

namespace {

constexpr double kPi = std::numbers::pi;

double round_to(double v, double step) { return std::round(v / step) * step; }

struct Face {
    int axis;   // 0, 1, 2
    bool plus;  // at size[axis] (else at 0)
};

double component(const Vec3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
void set_component(Vec3& v, int axis, double value) { (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = value; }

Vec3 outward(const Face& f) {
    Vec3 n{0, 0, 0};
    set_component(n, f.axis, f.plus ? 1.0 : -1.0);
    return n;
}

// A point on the face, `margin` from its edges.
Vec3 point_on(const Face& f, const Vec3& size, double margin, Random& rng) {
    Vec3 p{0, 0, 0};
    for (int k = 0; k < 3; ++k)
        set_component(p, k, k == f.axis ? (f.plus ? component(size, k) : 0.0)
                                         : rng.uniform(margin, component(size, k) - margin));
    return p;
}

// `dir` turned by a random angle up to `max_angle` about a random axis perpendicular to it.
Vec3 tilted(const Vec3& dir, double max_angle, Random& rng) {
    const Vec3 helper = std::abs(dir.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = unit(cross(dir, helper)), v = cross(dir, u);
    const double phi = rng.uniform(0, 2 * kPi), angle = rng.uniform(0, max_angle);
    const Vec3 side = std::cos(phi) * u + std::sin(phi) * v;
    return unit(std::cos(angle) * dir + std::sin(angle) * side);
}

struct Candidate {
    PipeSpec pipe;
    PipeSamples samples;
};

std::optional<Candidate> draw_pipe(const HostSpec& host, double d, Random& rng) {
    const Vec3 size = host.size;
    const double margin = 0.6 + 4 * d;
    const Face a{rng.integer(0, 2), rng.integer(0, 1) == 1};
    const Face b{rng.integer(0, 2), rng.integer(0, 1) == 1};
    if (component(size, a.axis) < 2.5 || component(size, b.axis) < 2.5) return std::nullopt;
    const Vec3 A = point_on(a, size, margin, rng), B = point_on(b, size, margin, rng);
    const bool u_bend = a.axis == b.axis && a.plus == b.plus;
    if (u_bend && norm(B - A) < 1.5) return std::nullopt;

    const double depth_a = component(size, a.axis), depth_b = component(size, b.axis);
    const double lead_a = rng.uniform(0.15, 0.25) * depth_a, lead_b = rng.uniform(0.15, 0.25) * depth_b;
    const Vec3 ta = tilted(-1.0 * outward(a), 20.0 * kPi / 180, rng);
    const Vec3 tb = tilted(outward(b), 20.0 * kPi / 180, rng);

    PipeSpec pipe;
    pipe.kind = PathKind::Bspline;
    pipe.diameter = d;
    pipe.points.push_back(A);
    pipe.points.push_back(A + lead_a * ta);
    // Waypoints keep 1 from the faces; a U-bend gets one below the middle of its two ends.
    const double inner = 1.0;
    if (u_bend) {
        Vec3 w = 0.5 * (A + B);
        const double depth = rng.uniform(0.35, 0.7) * depth_a;
        set_component(w, a.axis, a.plus ? depth_a - depth : depth);
        pipe.points.push_back(w);
    } else {
        const int waypoints = rng.integer(0, 2);
        for (int i = 0; i < waypoints; ++i)
            pipe.points.push_back({rng.uniform(inner, size.x - inner), rng.uniform(inner, size.y - inner),
                                   rng.uniform(inner, size.z - inner)});
    }
    pipe.points.push_back(B - lead_b * tb);
    pipe.points.push_back(B);

    // Cheap tests first: the curve lies in the hull of its control points, so controls outside
    // the box (or too close to it) can be rejected before building anything.
    for (std::size_t i = 1; i + 1 < pipe.points.size(); ++i)
        if (signed_boundary_distance(host, pipe.points[i]) < 2 * d) return std::nullopt;

    CentreLine line;
    try {
        line = make_centre_line(pipe, host, 1);
    } catch (const Error&) {
        return std::nullopt;
    }
    if (min_curvature_radius(line) < 4 * d) return std::nullopt;
    Candidate c{pipe, {sample_path(line, d), d / 2}};
    // Inside everywhere but at its two end points, clear of the faces away from its ends, clear
    // of itself.
    for (std::size_t i = 1; i + 1 < c.samples.points.size(); ++i)
        if (signed_boundary_distance(host, c.samples.points[i]) <= 0) return std::nullopt;
    const double end_zone = std::max(lead_a, lead_b);
    const Clearance own = measure_clearance({c.samples}, host, end_zone);
    if (own.boundary_gap < 2 * d || own.self_gap < 2 * d) return std::nullopt;
    return c;
}

}  // namespace

BlockSpec random_block_spec(std::uint64_t seed) {
    Random rng(seed);
    BlockSpec spec;
    spec.name = "seed " + std::to_string(seed);
    spec.length_unit = "model units";
    spec.host.kind = HostSpec::Kind::Box;
    spec.host.size = {round_to(rng.uniform(4, 10), 0.5), round_to(rng.uniform(4, 10), 0.5), round_to(rng.uniform(4, 10), 0.5)};

    const int wanted = rng.integer(1, 12);
    const double base = rng.uniform(0.05, 0.15);
    std::vector<PipeSamples> placed;
    constexpr int kTriesPerPipe = 60;
    for (int n = 0; n < wanted; ++n) {
        const double d = round_to(base * rng.uniform(0.7, 1.3), 0.001);
        // The first pipe always finds a place in a box this size; keep drawing until it does.
        const int tries = placed.empty() ? 100 * kTriesPerPipe : kTriesPerPipe;
        for (int t = 0; t < tries; ++t) {
            std::optional<Candidate> c = draw_pipe(spec.host, d, rng);
            if (!c) continue;
            const bool clear = std::all_of(placed.begin(), placed.end(), [&](const PipeSamples& other) {
                return pipe_gap(c->samples, other) >= 3 * std::max(c->samples.radius, other.radius) * 2;
            });
            if (!clear) continue;
            placed.push_back(c->samples);
            spec.pipes.push_back(std::move(c->pipe));
            break;
        }
    }
    if (spec.pipes.empty()) throw Error("random block " + std::to_string(seed) + ": could not place any pipe");
    return spec;
}

}  // namespace tubemesh::geom
