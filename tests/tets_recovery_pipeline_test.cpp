// Boundary recovery on real tet fronts: built-in blocks through the pipeline up to the pyramid
// layer; the front (mesh node ids) is compacted to the points it uses. Each front must give a
// domain whose tets fill exactly the volume it encloses, with every front triangle a face.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/pipeline/pipeline.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/tets/recovery/boundary_recovery.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/random_block.hpp"
#include "geom/prepare.hpp"
#include "tests/support/tet_domain_volume.hpp"

namespace {

using namespace tubemesh;

void recover_and_check(const geom::BlockSpec& spec, const std::string& label) {
    const geom::BuiltBlock block = geom::build_block(spec);
    const geom::PreparedModel prepared = geom::prepare_model(block.model);
    const PipelineResult r = run_pipeline(prepared.pipeline_input(), {}, Stage::Pyramids);
    ASSERT_FALSE(r.tet_front.empty());
    std::vector<index_t> id(r.mesh.point_count(), kNoIndex);
    std::vector<double> xyz;
    std::vector<index_t> front;
    for (index_t v : r.tet_front) {
        if (id[v] == kNoIndex) {
            id[v] = static_cast<index_t>(xyz.size() / 3);
            xyz.insert(xyz.end(), {r.mesh.x[v], r.mesh.y[v], r.mesh.z[v]});
        }
        front.push_back(id[v]);
    }
    tets::RecoveryStats st;
    const tets::TetDomain d = tets::recover_boundary(xyz, front, Parallelism{}, {}, &st);
    double enclosed = 0;
    const Vec3 o = tets::point_vec(d, 0);
    for (std::size_t i = 0; i < front.size(); i += 3)
        enclosed += tet_volume(o, tets::point_vec(d, front[i]), tets::point_vec(d, front[i + 1]),
                               tets::point_vec(d, front[i + 2]));
    std::size_t open = 0;
    for (index_t t = 0; t < d.tets.size(); ++t) {
        const index_t* v = d.tets.vertex(t);
        ASSERT_GT(predicates::orient3d(d.point(v[0]), d.point(v[1]), d.point(v[2]), d.point(v[3])), 0);
        for (int f = 0; f < 4; ++f) {
            const index_t nb = d.tets.neighbour(4 * t + f);
            if (nb == delaunay::kNoAdjacent) ++open;
            else EXPECT_EQ(d.tets.neighbour(nb), 4 * t + static_cast<index_t>(f));
        }
    }
    EXPECT_EQ(open, front.size() / 3);
    const double volume = tubemesh::testing::domain_volume(d);
    EXPECT_NEAR(volume, enclosed, 1e-9 * std::abs(enclosed));
    std::printf("%s: %zu front triangles, %u tets, missing edges %u faces %u, flips23 %llu removals %llu, "
                "steiner %u inserted %u removed, %.3f s\n",
                label.c_str(), front.size() / 3, st.tets, st.missing_edges, st.missing_faces,
                (unsigned long long)st.flips23, (unsigned long long)st.edge_removals, st.steiner_inserted,
                st.steiner_removed, st.seconds_total);
}

class RecoveryPreset : public ::testing::TestWithParam<const char*> {};
TEST_P(RecoveryPreset, FrontIsRecovered) { recover_and_check(geom::preset_spec(GetParam()), GetParam()); }
#ifndef TUBEMESH_RECOVERY_HEAVY
INSTANTIATE_TEST_SUITE_P(Presets, RecoveryPreset, ::testing::Values("paper-ex2", "paper-ex3"));
#else
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(RecoveryPreset);
#endif

class RecoverySeed : public ::testing::TestWithParam<int> {};
TEST_P(RecoverySeed, FrontIsRecovered) {
    recover_and_check(geom::random_block_spec(static_cast<std::uint64_t>(GetParam())), "seed" + std::to_string(GetParam()));
}
// 10 seeds by default; the heavy variant (test_tets_recovery_pipeline_heavy) runs seeds 11-50.
#ifdef TUBEMESH_RECOVERY_HEAVY
INSTANTIATE_TEST_SUITE_P(Seeds, RecoverySeed, ::testing::Range(11, 51));
#else
INSTANTIATE_TEST_SUITE_P(Seeds, RecoverySeed, ::testing::Range(1, 11));
#endif

}  // namespace
