#include "tests/support/sweep_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "engine/quality/quality.hpp"

namespace tubemesh::sweep_testing {

RingFigures measure_rings(const Scene& scene, const HybridMesh& mesh, const SweepResult& result) {
    RingFigures f;
    f.min_jacobian = std::numeric_limits<double>::infinity();
    double sum = 0;
    const CellBlock& hexes = mesh.block(CellKind::Hex);
    for (std::size_t h = 0; h < hexes.region.size(); ++h) {
        std::array<Vec3, 8> p;
        for (std::size_t v = 0; v < 8; ++v) p[v] = mesh.point(hexes.nodes[8 * h + v]);
        const HexQuality q = hex_quality(p);
        f.min_jacobian = std::min(f.min_jacobian, q.scaled_jacobian);
        f.max_condition = std::max(f.max_condition, q.condition);
        sum += q.scaled_jacobian;
        ++f.hexes;
    }
    f.mean_jacobian = f.hexes ? sum / f.hexes : 0;

    for (const TubeRing& ring : result.rings) {
        const TubeData& tube = scene.tubes[ring.tube];
        const double r = scene.specs[ring.tube].radius;
        for (index_t i = 0; i < ring.stations; ++i)
            for (index_t k = 0; k < ring.circumferential; ++k) {
                const Vec3 p = mesh.point(ring.node(i, 0, k));
                double d = std::numeric_limits<double>::infinity();
                for (index_t face : tube.wall_faces) d = std::min(d, scene.surface(face).distance_on_face(p));
                f.wall_error = std::max(f.wall_error, d / r);
            }
        for (int e = 0; e < 2; ++e) {
            const TestSurface& host = scene.surface(e == 0 ? tube.host1 : tube.host2);
            const index_t i = e == 0 ? 0 : ring.stations - 1;
            for (index_t j = 0; j <= ring.radial_layers; ++j)
                for (index_t k = 0; k < ring.circumferential; ++k) {
                    const Projection pr = host.project(mesh.point(ring.node(i, j, k)), std::nullopt);
                    f.host_error = std::max(f.host_error, pr.ok ? pr.distance / r : std::numeric_limits<double>::infinity());
                }
        }
    }
    f.check = check_mesh(with_outer_quads(mesh, result));
    return f;
}

HybridMesh with_outer_quads(HybridMesh mesh, const SweepResult& result) {
    const index_t group = mesh.surface_group_id("ring_outer");
    for (std::size_t q = 0; q < result.outer_quads.size(); q += 4)
        mesh.add_face(FaceKind::Quad, std::span<const index_t>(result.outer_quads.data() + q, 4), group);
    return mesh;
}

RingFigures expect_acceptance(const Scene& scene) { return expect_acceptance(scene, scene.options()); }

RingFigures expect_acceptance(const Scene& scene, const SweepOptions& options) {
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), options);
    const RingFigures f = measure_rings(scene, mesh, result);
    EXPECT_GT(f.hexes, 0u);
    EXPECT_GE(f.min_jacobian, 0.5);
    EXPECT_LE(f.max_condition, 4.0);
    EXPECT_GE(f.mean_jacobian, 0.70);
    EXPECT_LE(f.wall_error, 1e-7);
    EXPECT_LE(f.host_error, 1e-7);
    EXPECT_TRUE(f.check.ok()) << describe(f.check);
    // The sweep's own statistics agree with the independent measurement.
    EXPECT_NEAR(result.stats.min_scaled_jacobian, f.min_jacobian, 1e-12);
    EXPECT_NEAR(result.stats.max_condition, f.max_condition, 1e-9);
    EXPECT_EQ(result.stats.hexes, f.hexes);
    return f;
}

}  // namespace tubemesh::sweep_testing
