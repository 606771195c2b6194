// Input the sweep refuses, with a message naming the tube, and leaving the mesh unchanged.
#include <gtest/gtest.h>

#include <string>

#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {
namespace {

std::string failure(const Scene& scene, const std::vector<TubeData>& tubes, const SweepOptions& options) {
    HybridMesh mesh;
    mesh.add_point(1, 2, 3);
    const HybridMesh before = mesh;
    try {
        sweep_tubes(mesh, tubes, scene.lookup(), options);
    } catch (const Error& e) {
        EXPECT_TRUE(mesh == before);
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return {};
}

std::string failure(const Scene& scene, const std::vector<TubeData>& tubes) {
    return failure(scene, tubes, scene.options());
}

TEST(SweepErrors, RingsOfDifferentSizes) {
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    auto tubes = scene.tubes;
    tubes[0].ring2.pop_back();
    const std::string what = failure(scene, tubes);
    EXPECT_NE(what.find("tube 1"), std::string::npos) << what;
    EXPECT_NE(what.find("same number"), std::string::npos) << what;
}

TEST(SweepErrors, MissingSurfaceMap) {
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    auto tubes = scene.tubes;
    tubes[0].host2 = 99;
    EXPECT_NE(failure(scene, tubes).find("face 99 has no surface map"), std::string::npos);
}

TEST(SweepErrors, RingsTurningOppositeWays) {
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    auto tubes = scene.tubes;
    std::reverse(tubes[0].ring2.begin() + 1, tubes[0].ring2.end());
    EXPECT_NE(failure(scene, tubes).find("opposite ways"), std::string::npos);
}

TEST(SweepErrors, ARingFarFromWhereTheWallMeetsTheHost) {
    // A tenth of the radius out: no loop's tolerance explains that, the ring is not the tube's.
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    auto tubes = scene.tubes;
    for (Vec3& p : tubes[0].ring2) p = {1.1 * p.x, 1.1 * p.y, p.z};
    const std::string what = failure(scene, tubes);
    EXPECT_NE(what.find("tube 1"), std::string::npos) << what;
    EXPECT_NE(what.find("ring2 node 0"), std::string::npos) << what;
    EXPECT_NE(what.find("where the wall meets host face"), std::string::npos) << what;
}

TEST(SweepErrors, TheFirstFailingTubeIsNamed) {
    Scene scene = straight_scene(0.02, 0.04, 1.0);
    auto tubes = scene.tubes;
    tubes.push_back(tubes[0]);
    tubes.push_back(tubes[0]);
    tubes[1].stations.resize(1);
    tubes[2].ring1.resize(3);
    const std::string what = failure(scene, tubes);
    EXPECT_NE(what.find("tube 2"), std::string::npos) << what;
}

TEST(SweepErrors, ABendTooTightForTheRingFolds) {
    // r + St = 1.5 times the bend radius: the ring's inner side crosses the bend's axis.
    const Scene scene = u_bend_scene(0.02, 0.1, 0.08, false);
    const std::string what = failure(scene, scene.tubes);
    EXPECT_NE(what.find("lower St"), std::string::npos) << what;
}

TEST(SweepErrors, AHostTooObliqueForTheTube) {
    const Scene scene = oblique_scene(0.02, 0.04, 84 * kPi / 180, 0, 0.5);
    const std::string what = failure(scene, scene.tubes);
    EXPECT_NE(what.find("too oblique"), std::string::npos) << what;
}

TEST(SweepErrors, BadOptions) {
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    SweepOptions options = scene.options();
    options.radial_layers = 0;
    EXPECT_NE(failure(scene, scene.tubes, options).find("radial_layers"), std::string::npos);
}

}  // namespace
}  // namespace tubemesh::sweep_testing
