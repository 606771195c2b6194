// The acceptance bar on 50 random tubes: random radius and St (0.4 r to 3 r), centre lines of
// straight pieces and bends in random planes, hosts (planes, convex and concave cylinders) met
// at up to 35 degrees, geom's references or none, either ring handedness. Paths that come back
// within 2.2 (r + St) of themselves (overlapping rings: an invalid solid) are drawn again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <random>

#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_checks.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {
namespace {

// The envelope the sweep is held to: bends no tighter than R = 1.5 (r + St) (geom's sizing
// guard allows 1.05), hosts within 35 degrees of square (beyond, see SweepRings' oil holes).
constexpr double kTightestBend = 1.5;
constexpr double kMostOblique = 35 * kPi / 180;

class Random {
public:
    explicit Random(unsigned seed) : rng_(seed) {}
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
    bool chance(double p) { return uniform(0, 1) < p; }
    V unit() {
        const V v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        return v.norm() > 0.1 ? V(v.normalized()) : unit();
    }
    V orthogonal_to(const V& t) {
        const V v = unit();
        const V p = v - v.dot(t) * t;
        return p.norm() > 0.1 ? V(p.normalized()) : orthogonal_to(t);
    }

private:
    std::mt19937_64 rng_;
};

index_t random_host(Scene& scene, Random& rnd, const V& at, const V& away, double scale) {
    // `away`: the direction out of the solid along the tube; tilt it by up to kMostOblique.
    const V normal = Eigen::AngleAxisd(rnd.uniform(0, kMostOblique), rnd.orthogonal_to(away)) * away;
    switch (rnd.integer(0, 2)) {
        case 0: return scene.plane(at, normal);
        case 1: return scene.cylinder(at, normal, rnd.orthogonal_to(normal), scale * rnd.uniform(5, 20), true);
        default: return scene.cylinder(at, normal, rnd.orthogonal_to(normal), scale * rnd.uniform(5, 20), false);
    }
}

// Smallest distance between two points of the path more than `gap` apart along it.
double self_distance(const Path& path, double step, double gap) {
    std::vector<V> points;
    for (double s = 0; s <= path.length(); s += step) points.push_back(path.point(s));
    const std::size_t skip = static_cast<std::size_t>(std::ceil(gap / step));
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < points.size(); ++a)
        for (std::size_t b = a + skip; b < points.size(); ++b) nearest = std::min(nearest, (points[a] - points[b]).norm());
    return nearest;
}

Scene random_scene(unsigned seed) {
    Random rnd(seed);
    TubeSpec spec;
    spec.radius = rnd.uniform(0.005, 0.1);
    spec.sweep_size = spec.radius * rnd.uniform(0.4, 3.0);
    const double scale = spec.radius + spec.sweep_size;
    spec.lead = 3 * scale;
    spec.zero_reference = rnd.chance(0.3);
    spec.left_handed = rnd.chance(0.2);
    const V t = rnd.unit();
    const V reference = rnd.orthogonal_to(t);
    // A path that comes back near itself would make a solid whose rings overlap: draw again.
    auto draw = [&] {
        Path path(V::Zero(), t, reference);
        path.straight(spec.lead + scale * rnd.uniform(4, 10));
        for (int pieces = rnd.integer(0, 4); pieces > 0; --pieces) {
            if (rnd.chance(0.6))
                path.arc(scale * rnd.uniform(kTightestBend, 3 * kTightestBend), rnd.uniform(kPi / 6, kPi),
                         rnd.uniform(0, 2 * kPi));
            else
                path.straight(scale * rnd.uniform(2, 8));
        }
        path.straight(spec.lead + scale * rnd.uniform(4, 10));
        return path;
    };
    Path path = draw();
    while (self_distance(path, scale / 4, 5 * scale) < 2.2 * scale) path = draw();
    Scene scene;
    spec.host1 = random_host(scene, rnd, path.point(spec.lead), -path.tangent(spec.lead), scale);
    const double end = path.length() - spec.lead;
    spec.host2 = random_host(scene, rnd, path.point(end), path.tangent(end), scale);
    scene.tube(path, spec);
    return scene;
}

TEST(SweepRandom, FiftySeedsMeetTheAcceptanceBar) {
    double min_j = 1, min_mean = 1, max_cond = 0;
    for (unsigned seed = 0; seed < 50; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const RingFigures f = expect_acceptance(random_scene(seed));
        min_j = std::min(min_j, f.min_jacobian);
        min_mean = std::min(min_mean, f.mean_jacobian);
        max_cond = std::max(max_cond, f.max_condition);
    }
    std::printf("[ figures  ] 50 random tubes: J_m min %.3f, lowest mean %.3f, Cond max %.3f\n", min_j, min_mean,
                max_cond);
}

}  // namespace
}  // namespace tubemesh::sweep_testing
