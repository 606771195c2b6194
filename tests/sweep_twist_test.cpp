// No twist: circumferential node k stays on the same side of the pipe from end to end, along
// a 180-degree bend, a serpentine and a non-planar path, with geom's references and with the
// sweep's own rotation-minimising frames.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {
namespace {

// Arc length of the path point nearest to p: dense search, then Newton on (point - p)·tangent.
double nearest_s(const Path& path, const V& p) {
    double best = 0, best_d = std::numeric_limits<double>::infinity();
    constexpr int kSamples = 20000;
    for (int i = 0; i <= kSamples; ++i) {
        const double s = path.length() * i / kSamples;
        const double d = (path.point(s) - p).squaredNorm();
        if (d < best_d) best_d = d, best = s;
    }
    for (int it = 0; it < 20; ++it) best += (p - path.point(best)).dot(path.tangent(best));
    return best;
}

// Largest angle, over all stations and nodes, between node k's direction from the centre line
// and the direction 2πk/n from the path's own transported reference (right-handed rings).
double worst_side_error(const Scene& scene, const HybridMesh& mesh, const TubeRing& ring) {
    const Path& path = scene.paths[ring.tube];
    const index_t n = ring.circumferential;
    double worst = 0;
    for (index_t i = 0; i < ring.stations; ++i) {
        V centre = V::Zero();
        for (index_t k = 0; k < n; ++k) centre += eig(mesh.point(ring.node(i, 0, k))) / n;
        const double s = nearest_s(path, centre);
        const V t = path.tangent(s), ref = path.reference(s), c = path.point(s);
        for (index_t k = 0; k < n; ++k) {
            V d = eig(mesh.point(ring.node(i, ring.radial_layers, k))) - c;
            d -= d.dot(t) * t;
            const double a = 2 * kPi * k / n;
            const V want = std::cos(a) * ref + std::sin(a) * t.cross(ref);
            worst = std::max(worst, std::acos(std::clamp(d.normalized().dot(want), -1.0, 1.0)));
        }
    }
    return worst;
}

double sweep_and_measure(const Scene& scene, bool expect_fallback) {
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    EXPECT_EQ(result.rings[0].frame_fallback, expect_fallback);
    return worst_side_error(scene, mesh, result.rings[0]);
}

constexpr double kOneDegree = kPi / 180;

TEST(SweepTwist, HalfTorusBendWithReferences) {
    EXPECT_LT(sweep_and_measure(u_bend_scene(0.016, 0.032, 0.24, false), false), kOneDegree);
}

TEST(SweepTwist, HalfTorusBendWithFrames) {
    EXPECT_LT(sweep_and_measure(u_bend_scene(0.016, 0.032, 0.24, true), true), kOneDegree);
}

TEST(SweepTwist, SerpentineWithReferences) {
    EXPECT_LT(sweep_and_measure(serpentine_scene(0.016, 0.032, 5, 1.0, 0.3, false), false), kOneDegree);
}

TEST(SweepTwist, SerpentineWithFrames) {
    EXPECT_LT(sweep_and_measure(serpentine_scene(0.016, 0.032, 5, 1.0, 0.3, true), true), kOneDegree);
}

TEST(SweepTwist, NodeZeroStaysOnTopOfAPlanarSerpentine) {
    // The plainest statement of "no twist": the path lies in z = 0 and node 0 starts at +z.
    const Scene scene = serpentine_scene(0.016, 0.032, 4, 1.0, 0.3, true);
    HybridMesh mesh;
    const TubeRing ring = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options()).rings[0];
    for (index_t i = 0; i < ring.stations; ++i) {
        const V wall = eig(mesh.point(ring.node(i, 0, 0)));
        const V below = scene.paths[0].point(nearest_s(scene.paths[0], wall));
        EXPECT_LT(std::acos((wall - below).normalized().z()), 0.1 * kOneDegree) << "station " << i;
    }
}

TEST(SweepTwist, NonPlanarPathWithFrames) {
    // Bends in three different planes: the transported frame turns about the tangent, and the
    // discrete rotation-minimising frames must follow it.
    Scene scene;
    TubeSpec spec{0.016, 0.032, 0.2};
    spec.zero_reference = true;
    Path path(V(0, 0, -spec.lead), V(0, 0, 1), V(1, 0, 0));
    path.straight(spec.lead + 0.3);
    path.arc(0.3, kPi / 2, 0.4);
    path.straight(0.2);
    path.arc(0.25, 2 * kPi / 3, 2.0);
    path.arc(0.4, kPi / 3, -1.2);
    path.straight(0.3 + spec.lead);
    spec.host1 = scene.plane(path.point(spec.lead), -path.tangent(spec.lead));
    const double end = path.length() - spec.lead;
    spec.host2 = scene.plane(path.point(end), path.tangent(end));
    scene.tube(path, spec);
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    EXPECT_TRUE(result.rings[0].frame_fallback);
    EXPECT_LT(std::abs(result.rings[0].twist), 1e-3);  // the discrete frames end where the exact ones do
    EXPECT_LT(worst_side_error(scene, mesh, result.rings[0]), kOneDegree);
    EXPECT_GE(result.stats.min_scaled_jacobian, 0.5);
}

}  // namespace
}  // namespace tubemesh::sweep_testing
