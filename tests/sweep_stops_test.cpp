// Rings that stop on a cross-section inside the solid (TubeData::stops): the stopped end's
// quads are pyramid fronts facing along the pipe, not boundary faces, and the end holds no hole
// of any face.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/check/mesh_check.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_checks.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {
namespace {

Vec3 quad_normal(const HybridMesh& mesh, const index_t* q) {
    const Vec3 a = mesh.point(q[0]), b = mesh.point(q[1]), c = mesh.point(q[2]), d = mesh.point(q[3]);
    return cross(c - a, d - b);
}

// The ring with its outer and stop quads as boundary faces: closed, so check_mesh sees every
// hex face matched or on the boundary once.
HybridMesh closed_ring(HybridMesh mesh, const SweepResult& result) {
    mesh = with_outer_quads(std::move(mesh), result);
    const index_t group = mesh.surface_group_id("ring_stop");
    for (std::size_t q = 0; q < result.stop_quads.size(); q += 4)
        mesh.add_face(FaceKind::Quad, std::span<const index_t>(result.stop_quads.data() + q, 4), group);
    return mesh;
}

TEST(SweepStops, StoppedEndQuadsAreFrontsAlongThePipe) {
    Scene scene = straight_scene(0.02, 0.04, 0.6);
    scene.tubes[0].stops = {false, true};
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    const TubeRing& ring = result.rings[0];
    const index_t n = ring.circumferential, L = ring.radial_layers, m = ring.stations - 1;
    EXPECT_TRUE(ring.stopped[1]);
    EXPECT_FALSE(ring.stopped[0]);
    ASSERT_EQ(result.stop_quads.size(), 4u * L * n);
    EXPECT_EQ(result.end_quads.size(), 4u * 2 * L * n);  // every end's, in their places
    // Boundary quads: the wall's and the first end's only.
    EXPECT_EQ(mesh.face_count(FaceKind::Quad), m * n + L * n);
    EXPECT_EQ(ring.ends[1].host, 0u);
    EXPECT_EQ(ring.host_group[1], kNoIndex);
    for (std::size_t q = 0; q < result.stop_quads.size(); q += 4) {
        const Vec3 normal = quad_normal(mesh, result.stop_quads.data() + q);
        EXPECT_GT(normal.z, 0.99 * norm(normal));  // away from the ring, along the pipe
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(mesh.point(result.stop_quads[q + c]).z, 0.6, 1e-12);
    }
    const CheckReport check = check_mesh(closed_ring(mesh, result));
    EXPECT_TRUE(check.ok()) << describe(check);
}

TEST(SweepStops, ARingCanStopAtBothEnds) {
    Scene scene = straight_scene(0.02, 0.04, 0.5);
    scene.tubes[0].stops = {true, true};
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    const TubeRing& ring = result.rings[0];
    const index_t n = ring.circumferential, L = ring.radial_layers, m = ring.stations - 1;
    ASSERT_EQ(result.stop_quads.size(), 4u * 2 * L * n);
    EXPECT_EQ(mesh.face_count(FaceKind::Quad), m * n);
    // The first end's quads come first and face back along the pipe; the second's onwards.
    for (std::size_t q = 0; q < result.stop_quads.size(); q += 4) {
        const Vec3 normal = quad_normal(mesh, result.stop_quads.data() + q);
        const bool first = q < 4u * L * n;
        EXPECT_GT((first ? -1.0 : 1.0) * normal.z, 0.99 * norm(normal));
    }
    const CheckReport check = check_mesh(closed_ring(mesh, result));
    EXPECT_TRUE(check.ok()) << describe(check);
    // The prism between the wall's and the outer polygon of n sides, 0.5 long.
    const double polygon = 0.5 * n * std::sin(2 * kPi / n);
    EXPECT_NEAR(check.volume, polygon * (0.06 * 0.06 - 0.02 * 0.02) * 0.5, 1e-6);
}

}  // namespace
}  // namespace tubemesh::sweep_testing
