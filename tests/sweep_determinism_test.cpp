// The same mesh for every thread count: tubes are planned and placed in parallel, merged in
// tube order.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {
namespace {

struct SweepRun {
    HybridMesh mesh;
    SweepResult result;
};

SweepRun sweep_with_threads(const Scene& scene, int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    SweepRun run;
    run.result = sweep_tubes(run.mesh, scene.tubes, scene.lookup(), scene.options());
    return run;
}

TEST(SweepDeterminism, OneTwoAndFourThreadsGiveTheSameBytes) {
    Scene scene;
    TubeSpec spec{0.016, 0.032, 0.1};
    spec.host1 = scene.plane(V(0, 0, 0), V(-1, 0, 0));
    spec.host2 = spec.host1;
    for (int t = 0; t < 5; ++t) {
        spec.zero_reference = t % 2 == 1;
        scene.tube(serpentine_path(2 + t % 3 * 2, 2.0, 0.3, spec.lead, V(0, 0, 0.2 * t)), spec);
    }
    const SweepRun one = sweep_with_threads(scene, 1);
    for (int threads : {2, 4}) {
        const SweepRun other = sweep_with_threads(scene, threads);
        EXPECT_TRUE(one.mesh == other.mesh) << threads << " threads";
        EXPECT_EQ(one.result.outer_quads, other.result.outer_quads);
        EXPECT_EQ(one.result.end_quads, other.result.end_quads);
        EXPECT_EQ(one.result.stats.mean_scaled_jacobian, other.result.stats.mean_scaled_jacobian);
        EXPECT_EQ(one.result.stats.max_wall_correction, other.result.stats.max_wall_correction);
    }
}

}  // namespace
}  // namespace tubemesh::sweep_testing
