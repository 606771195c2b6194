#include "tests/support/sweep_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tubemesh::sweep_testing {
namespace {

V rotate(const V& v, const V& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()) * v; }

// Signed distance of p from a surface, positive on the side its outward normal points to.
double signed_distance(const TestSurface& s, const V& p) {
    const Projection pr = s.project(vec(p), std::nullopt);
    if (!pr.ok) throw std::runtime_error("sweep scene: no foot point on a host");
    return (p - eig(pr.point)).dot(eig(s.normal(pr.uv)));
}

// Root of f near s by Newton steps with a central-difference slope.
template <class F>
double solve_near(F f, double s, double scale) {
    for (int it = 0; it < 60; ++it) {
        const double h = 1e-6 * scale;
        const double slope = (f(s + h) - f(s - h)) / (2 * h);
        if (!(std::abs(slope) > 1e-12)) throw std::runtime_error("sweep scene: the tube runs along a host");
        const double step = f(s) / slope;
        s -= step;
        if (std::abs(step) < 1e-15 * scale) break;
    }
    return s;
}

}  // namespace

Path::Path(const V& start, const V& tangent, const V& reference)
    : end_point_(start), end_tangent_(tangent.normalized()) {
    end_reference_ = (reference - end_tangent_.dot(reference) * end_tangent_).normalized();
}

void Path::straight(double length) {
    Piece p;
    p.s0 = this->length();
    p.length = length;
    p.start = end_point_;
    p.tangent = end_tangent_;
    p.reference = end_reference_;
    pieces_.push_back(p);
    end_point_ += length * end_tangent_;
}

void Path::arc(double R, double angle, double plane) {
    Piece p;
    p.arc = true;
    p.s0 = this->length();
    p.length = R * angle;
    p.start = end_point_;
    p.tangent = end_tangent_;
    p.reference = end_reference_;
    const V towards = std::cos(plane) * end_reference_ + std::sin(plane) * end_tangent_.cross(end_reference_);
    p.centre = end_point_ + R * towards;
    p.axis = end_tangent_.cross(towards);
    p.R = R;
    pieces_.push_back(p);
    end_point_ = p.centre + rotate(end_point_ - p.centre, p.axis, angle);
    end_tangent_ = rotate(end_tangent_, p.axis, angle);
    end_reference_ = rotate(end_reference_, p.axis, angle);
}

const Path::Piece& Path::piece_at(double s) const {
    for (std::size_t i = pieces_.size(); i-- > 0;)
        if (pieces_[i].s0 <= s) return pieces_[i];
    return pieces_.front();
}

V Path::point(double s) const {
    if (s < 0) return pieces_.front().start + s * pieces_.front().tangent;
    if (s > length()) return end_point_ + (s - length()) * end_tangent_;
    const Piece& p = piece_at(s);
    const double u = s - p.s0;
    if (!p.arc) return p.start + u * p.tangent;
    return p.centre + rotate(p.start - p.centre, p.axis, u / p.R);
}

V Path::tangent(double s) const {
    if (s < 0) return pieces_.front().tangent;
    if (s > length()) return end_tangent_;
    const Piece& p = piece_at(s);
    return p.arc ? rotate(p.tangent, p.axis, (s - p.s0) / p.R) : p.tangent;
}

V Path::reference(double s) const {
    if (s < 0) return pieces_.front().reference;
    if (s > length()) return end_reference_;
    const Piece& p = piece_at(s);
    return p.arc ? rotate(p.reference, p.axis, (s - p.s0) / p.R) : p.reference;
}

index_t Scene::add(std::unique_ptr<TestSurface> s) {
    surfaces_.push_back(std::move(s));
    return static_cast<index_t>(surfaces_.size());
}

const TestSurface& Scene::surface(index_t id) const { return *surfaces_.at(id - 1); }

SurfaceLookup Scene::lookup() const {
    return [this](index_t id) -> const SurfaceMap* {
        return id >= 1 && id <= surfaces_.size() ? surfaces_[id - 1].get() : nullptr;
    };
}

SweepOptions Scene::options() const {
    SweepOptions o;
    for (const TubeSpec& spec : specs) o.tube_sweep_size.push_back(spec.sweep_size);
    return o;
}

index_t Scene::plane(const V& at, const V& normal) {
    return add(std::make_unique<PlaneFace>(static_cast<index_t>(surfaces_.size() + 1), at, normal, 1e4));
}

index_t Scene::cylinder(const V& at, const V& normal, const V& axis, double R, bool convex) {
    const V n = normal.normalized();
    const V a = convex ? V(at - R * n) : V(at + R * n);
    return add(std::make_unique<CylinderFace>(static_cast<index_t>(surfaces_.size() + 1), a, axis, at - a, R,
                                              ParamRange{0, 2 * kPi, true, 2 * kPi}, ParamRange{-1e4, 1e4}, convex));
}

std::size_t Scene::tube(const Path& path, const TubeSpec& spec) {
    const double r = spec.radius;
    TubeData t;
    for (const Path::Piece& p : path.pieces()) {
        const index_t id = static_cast<index_t>(surfaces_.size() + 1);
        if (p.arc)
            t.wall_faces.push_back(add(std::make_unique<TorusFace>(id, p.centre, p.axis, p.start - p.centre, p.R, r, 0,
                                                                   p.length / p.R, spec.clamped_walls)));
        else
            t.wall_faces.push_back(add(std::make_unique<CylinderFace>(id, p.start, p.tangent, p.reference, r,
                                                                      ParamRange{0, 2 * kPi, true, 2 * kPi},
                                                                      ParamRange{0, p.length}, false,
                                                                      spec.clamped_walls)));
    }
    t.host1 = spec.host1;
    t.host2 = spec.host2;
    const TestSurface& h1 = surface(spec.host1);
    const TestSurface& h2 = surface(spec.host2);
    const double scale = r + spec.sweep_size;
    const double s1 = solve_near([&](double s) { return signed_distance(h1, path.point(s)); }, spec.lead, scale);
    const double s2 =
        solve_near([&](double s) { return signed_distance(h2, path.point(s)); }, path.length() - spec.lead, scale);

    const int steps = std::max(1, static_cast<int>(std::lround((s2 - s1) / spec.sweep_size)));
    for (int i = 0; i <= steps; ++i) {
        const double s = s1 + (s2 - s1) * i / steps;
        const V ref = spec.zero_reference ? V::Zero() : path.reference(s);
        t.stations.push_back({vec(path.point(s)), vec(path.tangent(s)), vec(ref), r});
    }

    // Ring: generator line at angle a meets the host; nodes spaced by arc length from a = 0.
    const int n = spec.n > 0 ? spec.n : circumferential_count(r, spec.sweep_size);
    auto ring = [&](const TestSurface& host, double s_guess) {
        auto on_host = [&](double a) {
            auto generator = [&](double s) {
                const V tg = path.tangent(s), ref = path.reference(s);
                return V(path.point(s) + r * (std::cos(a) * ref + std::sin(a) * tg.cross(ref)));
            };
            const double s = solve_near([&](double q) { return signed_distance(host, generator(q)); }, s_guess, scale);
            return generator(s);
        };
        constexpr int kSamples = 2048;
        std::vector<double> length{0};
        V prev = on_host(0);
        for (int i = 1; i <= kSamples; ++i) {
            const V p = on_host(2 * kPi * i / kSamples);
            length.push_back(length.back() + (p - prev).norm());
            prev = p;
        }
        std::vector<Vec3> nodes;
        for (int k = 0; k < n; ++k) {
            const int kk = spec.left_handed ? (n - k) % n : k;
            const double target = length.back() * kk / n;
            const auto it = std::upper_bound(length.begin(), length.end(), target);
            const std::size_t hi = std::min<std::size_t>(static_cast<std::size_t>(it - length.begin()), kSamples);
            const std::size_t lo = hi - 1;
            const double f = (target - length[lo]) / (length[hi] - length[lo]);
            nodes.push_back(vec(on_host(2 * kPi * (static_cast<double>(lo) + f) / kSamples)));
        }
        return nodes;
    };
    t.ring1 = ring(h1, s1);
    t.ring2 = ring(h2, s2);
    tubes.push_back(std::move(t));
    paths.push_back(path);
    specs.push_back(spec);
    return tubes.size() - 1;
}

Scene straight_scene(double radius, double sweep_size, double thickness) {
    Scene scene;
    TubeSpec spec{radius, sweep_size, 2 * (radius + sweep_size)};
    spec.host1 = scene.plane(V(0, 0, 0), V(0, 0, -1));
    spec.host2 = scene.plane(V(0, 0, thickness), V(0, 0, 1));
    Path path(V(0, 0, -spec.lead), V(0, 0, 1), V(1, 0, 0));
    path.straight(thickness + 2 * spec.lead);
    scene.tube(path, spec);
    return scene;
}

Scene u_bend_scene(double radius, double sweep_size, double R, bool zero_reference) {
    Scene scene;
    TubeSpec spec{radius, sweep_size, 2 * (radius + sweep_size)};
    spec.zero_reference = zero_reference;
    spec.host1 = spec.host2 = scene.plane(V(0, 0, 0), V(-1, 0, 0));
    Path path(V(-spec.lead, -R, 0), V(1, 0, 0), V(0, 0, 1));
    path.straight(spec.lead);
    path.arc(R, kPi, -kPi / 2);  // towards +y
    path.straight(spec.lead);
    scene.tube(path, spec);
    return scene;
}

Path serpentine_path(int legs, double leg, double R, double lead, const V& origin) {
    Path path(origin + V(-lead, 0, 0), V(1, 0, 0), V(0, 0, 1));
    path.straight(lead + leg);
    for (int i = 1; i < legs; ++i) {
        // Heading +x, tangent x reference = -y: turning towards +y is plane -pi/2; heading -x, +pi/2.
        path.arc(R, kPi, i % 2 == 1 ? -kPi / 2 : kPi / 2);
        path.straight(i + 1 == legs ? leg + lead : leg);
    }
    return path;
}

Scene serpentine_scene(double radius, double sweep_size, int legs, double leg, double R, bool zero_reference,
                       bool clamped_walls) {
    Scene scene;
    TubeSpec spec{radius, sweep_size, 2 * (radius + sweep_size)};
    spec.zero_reference = zero_reference;
    spec.clamped_walls = clamped_walls;
    spec.host1 = scene.plane(V(0, 0, 0), V(-1, 0, 0));
    spec.host2 = legs % 2 == 0 ? spec.host1 : scene.plane(V(leg, 0, 0), V(1, 0, 0));
    scene.tube(serpentine_path(legs, leg, R, spec.lead), spec);
    return scene;
}

Scene oil_hole_scene(double radius, double sweep_size, double R, double angle, bool through_axis) {
    Scene scene;
    TubeSpec spec{radius, sweep_size, 2 * (radius + sweep_size)};
    // The journal's axis is y through the origin.
    const V direction = through_axis ? V(std::cos(angle), std::sin(angle), 0) : V(1, 0, 0);
    const V entry = through_axis ? V(-R, -R * std::tan(angle), 0) : V(-R * std::cos(angle), 0, R * std::sin(angle));
    const V normal(entry.x() / R, 0, entry.z() / R);
    const double length = through_axis ? 2 * R / std::cos(angle) : 2 * R * std::cos(angle);
    spec.host1 = spec.host2 = scene.cylinder(entry, normal, V(0, 1, 0), R, true);
    Path path(entry - spec.lead * direction, direction, through_axis ? V(0, 0, 1) : V(0, 1, 0));
    path.straight(length + 2 * spec.lead);
    scene.tube(path, spec);
    return scene;
}

Scene oblique_scene(double radius, double sweep_size, double angle1, double angle2, double R) {
    Scene scene;
    TubeSpec spec{radius, sweep_size, 4 * (radius + sweep_size)};
    const double length = 12 * (radius + sweep_size);
    spec.host1 = scene.plane(V(0, 0, 0), rotate(V(0, 0, -1), V(1, 0, 0), angle1));
    const V normal2 = rotate(V(0, 0, 1), V(0, 1, 0), angle2);
    spec.host2 = scene.cylinder(V(0, 0, length), normal2, V(0, 1, 0), R, false);
    Path path(V(0, 0, -spec.lead), V(0, 0, 1), V(1, 0, 0));
    path.straight(length + 2 * spec.lead);
    scene.tube(path, spec);
    return scene;
}

}  // namespace tubemesh::sweep_testing
