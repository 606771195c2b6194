// The ring's thickness is local (geom/sizing/ring_room.hpp): a straight pipe r = 0.05 along a
// 4 x 3 x 2 box at clearance c above its bottom face keeps the full St = 2r on the side away
// from the face, thins only towards it with shorter steps there, and meshes at every clearance
// down to a tenth of the radius within a small multiple of the centred pipe's elements (the
// paper's one St: 29,909 at c = 2r, 71,994 at r, 206,123 at r/2, 787,884 at r/4, refused at r/10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <string>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/mesh_file.hpp"

namespace tubemesh {
namespace {

constexpr double kRadius = 0.05;
// The pipe in the middle of the box: the paper's ring, no thinning anywhere.
constexpr double kCentred = 1 - kRadius;

geom::BlockSpec pipe_above_floor(double clearance) {
    const std::string z = std::to_string(clearance + kRadius);
    return geom::parse_block_spec(R"({"box": [4, 3, 2], "check_clearance": false, "pipes": [
        {"path": "line", "diameter": 0.1, "points": [[0, 1.5, )" + z + "], [4, 1.5, " + z + "]]}]}",
                                  "pipe above the floor");
}

std::size_t elements(const PipelineResult& r) {
    return r.mesh.cell_count(CellKind::Hex) + r.mesh.cell_count(CellKind::Pyramid) + r.mesh.cell_count(CellKind::Tet);
}

// Ring thickness (outer node's distance from its wall node) at the middle station, at the
// column facing the floor and at the one facing away.
struct Sides {
    double floor = 0, away = 0;
};
Sides ring_sides(const PipelineResult& r) {
    const TubeRing& ring = r.sweep.rings.at(0);
    const index_t i = ring.stations / 2;
    index_t low = 0, high = 0;
    for (index_t k = 0; k < ring.circumferential; ++k) {
        if (r.mesh.point(ring.node(i, 0, k)).z < r.mesh.point(ring.node(i, 0, low)).z) low = k;
        if (r.mesh.point(ring.node(i, 0, k)).z > r.mesh.point(ring.node(i, 0, high)).z) high = k;
    }
    const auto thickness = [&](index_t k) {
        return norm(r.mesh.point(ring.node(i, ring.radial_layers, k)) - r.mesh.point(ring.node(i, 0, k)));
    };
    return {thickness(low), thickness(high)};
}

TEST(LocalRing, IsTheDefault) { EXPECT_TRUE(MeshOptions{}.local_ring); }

TEST(LocalRing, FullAwayFromTheFloorThinTowardsIt) {
    const geom::MeshRun run = geom::mesh_spec(pipe_above_floor(kRadius), MeshOptions{}, Stage::Sweep);
    EXPECT_NEAR(run.sweep_size, 2 * kRadius, 1e-9);  // St is not cut for the whole pipe
    const Sides s = ring_sides(run.result);
    EXPECT_NEAR(s.away, 2 * kRadius, 1e-9);
    // The face is r away: a ring and its pyramids take 3.2 times the ring there.
    EXPECT_LT(s.floor, kRadius / 3.2);
    EXPECT_GT(s.floor, 0.2 * kRadius / 3.2);
    const TubeRing& ring = run.result.sweep.rings.at(0);
    EXPECT_NEAR(ring.thickest, 2 * kRadius, 1e-9);
    EXPECT_LT(ring.thinnest, kRadius / 3.2);
}

TEST(LocalRing, ThinRingTakesShorterSteps) {
    const geom::MeshRun centred = geom::mesh_spec(pipe_above_floor(kCentred), MeshOptions{}, Stage::Sweep);
    const geom::MeshRun close = geom::mesh_spec(pipe_above_floor(kRadius / 2), MeshOptions{}, Stage::Sweep);
    const TubeRing& full = centred.result.sweep.rings.at(0);
    const TubeRing& thin = close.result.sweep.rings.at(0);
    EXPECT_EQ(thin.circumferential, full.circumferential);
    // The step follows the narrow outer side over the floor: 1.5 x 2 (r + t) sin(pi / 8).
    EXPECT_LT(thin.axial_step, 0.5 * full.axial_step);
    EXPECT_GT(thin.stations, 2 * full.stations);
}

TEST(LocalRing, CentredPipeKeepsThePapersRing) {
    const geom::MeshRun local = geom::mesh_spec(pipe_above_floor(kCentred), MeshOptions{}, Stage::Sweep);
    EXPECT_TRUE(local.result.sweep.outer_quad_scale.empty());
    const Sides s = ring_sides(local.result);
    EXPECT_NEAR(s.floor, 2 * kRadius, 1e-9);
    EXPECT_NEAR(s.away, 2 * kRadius, 1e-9);
    MeshOptions global;
    global.local_ring = false;
    const geom::MeshRun paper = geom::mesh_spec(pipe_above_floor(kCentred), global, Stage::Sweep);
    EXPECT_TRUE(local.result.mesh == paper.result.mesh);
}

// Each clearance meshes, passes the check, keeps a hex ring, and stays within `factor` times the
// centred pipe's elements; its worst tet is at least 0.2 or a warning says why.
struct Clearance {
    const char* name;
    double clearance;
    double factor;
};

class ClearanceSeries : public ::testing::TestWithParam<Clearance> {};

std::size_t centred_elements() {
    static const std::size_t n = elements(geom::mesh_spec(pipe_above_floor(kCentred), MeshOptions{}).result);
    return n;
}

TEST_P(ClearanceSeries, MeshesWithARingAndFewElements) {
    const Clearance c = GetParam();
    const geom::MeshRun run = geom::mesh_spec(pipe_above_floor(c.clearance), MeshOptions{});
    const PipelineResult& r = run.result;
    EXPECT_EQ(r.reached, Stage::Tets);
    EXPECT_TRUE(r.check.violations.empty());
    ASSERT_EQ(r.sweep.rings.size(), 1u);
    EXPECT_GT(r.mesh.cell_count(CellKind::Hex), 0u);
    EXPECT_NEAR(r.sweep.rings[0].thickest, 2 * kRadius, 1e-9);
    EXPECT_LE(static_cast<double>(elements(r)), c.factor * static_cast<double>(centred_elements()));
    if (r.quality.tet_collapse.min < 0.2) {
        const bool told = std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) {
            return w.find("worst tet") != std::string::npos && w.find("triangles") != std::string::npos;
        });
        EXPECT_TRUE(told) << "worst tet " << r.quality.tet_collapse.min << " without a warning naming the cause";
    }
}

INSTANTIATE_TEST_SUITE_P(Floor, ClearanceSeries,
                         ::testing::Values(Clearance{"TwoRadii", 2 * kRadius, 2}, Clearance{"OneRadius", kRadius, 2},
                                           Clearance{"HalfARadius", kRadius / 2, 2},
                                           Clearance{"QuarterRadius", kRadius / 4, 2},
                                           Clearance{"TenthOfARadius", kRadius / 10, 3}),
                         [](const ::testing::TestParamInfo<Clearance>& info) { return std::string(info.param.name); });

TEST(LocalRing, SameMeshForOneAndTwoThreads) {
    MeshOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const geom::MeshRun a = geom::mesh_spec(pipe_above_floor(kRadius / 4), one);
    const geom::MeshRun b = geom::mesh_spec(pipe_above_floor(kRadius / 4), two);
    EXPECT_GT(a.result.mesh.cell_count(CellKind::Tet), 0u);
    EXPECT_TRUE(a.result.mesh == b.result.mesh);
}

}  // namespace
}  // namespace tubemesh
