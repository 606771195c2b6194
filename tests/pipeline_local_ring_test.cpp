// The ring's thickness is local (geom/sizing/ring_room.hpp): a straight pipe r = 0.05 along a
// 4 x 3 x 2 box at clearance c above its bottom face keeps the full St = 2r on the side away
// from the face and thins only towards it, meshes, passes the check, and takes far fewer
// elements than one St cut for the whole pipe (the paper's one St: 29,909 at c = 2r, 71,994 at
// c = r, 206,123 at c = r/2).
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

MeshOptions local_ring() {
    MeshOptions o;
    o.local_ring = true;
    return o;
}

constexpr double kRadius = 0.05;

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

TEST(LocalRing, FullAwayFromTheFloorThinTowardsIt) {
    const geom::MeshRun run = geom::mesh_spec(pipe_above_floor(kRadius), local_ring(), Stage::Sweep);
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

TEST(LocalRing, CentredPipeKeepsThePapersRing) {
    const geom::MeshRun run = geom::mesh_spec(pipe_above_floor(1 - kRadius), local_ring(), Stage::Sweep);
    EXPECT_TRUE(run.result.sweep.outer_quad_scale.empty());
    const Sides s = ring_sides(run.result);
    EXPECT_NEAR(s.floor, 2 * kRadius, 1e-9);
    EXPECT_NEAR(s.away, 2 * kRadius, 1e-9);
}

void expect_meshes_lighter(double clearance, std::size_t global_ring_elements) {
    const geom::MeshRun run = geom::mesh_spec(pipe_above_floor(clearance), local_ring());
    EXPECT_TRUE(run.result.check.violations.empty());
    EXPECT_GT(run.result.mesh.cell_count(CellKind::Hex), 0u);
    // The centred pipe takes about 19,800; the global ring many times that.
    EXPECT_LT(elements(run.result), global_ring_elements * 3 / 4);
    EXPECT_LT(elements(run.result), std::size_t{2 * 19836});
}

TEST(LocalRing, TwoRadiiFromTheFloorMeshes) { expect_meshes_lighter(2 * kRadius, 29909); }
TEST(LocalRing, OneRadiusFromTheFloorMeshes) { expect_meshes_lighter(kRadius, 71994); }

}  // namespace
}  // namespace tubemesh
