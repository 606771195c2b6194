// Hex rings on synthetic tubes: quality, nodes on wall and hosts, conformity of the ring mesh,
// and what the result hands to the surface mesher and the pyramids.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>

#include "engine/check/mesh_check.hpp"
#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_checks.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {
namespace {

void print(const char* name, const RingFigures& f) {
    std::printf("[ figures  ] %-28s hexes %6u  J_m min %.3f mean %.3f  Cond max %.3f  wall %.1e host %.1e\n", name,
                f.hexes, f.min_jacobian, f.mean_jacobian, f.max_condition, f.wall_error, f.host_error);
}

TEST(SweepRings, StraightPipeThroughASlab) {
    print("straight r 0.02 St 0.04", expect_acceptance(straight_scene(0.02, 0.04, 1.0)));
    print("straight r 0.02 St 0.01", expect_acceptance(straight_scene(0.02, 0.01, 0.3)));
    print("straight r 0.02 St 0.14", expect_acceptance(straight_scene(0.02, 0.14, 2.0)));
}

TEST(SweepRings, HalfTorusUBendOnOneFace) {
    print("U-bend R/(r+St) 5", expect_acceptance(u_bend_scene(0.016, 0.032, 0.24, false)));
    print("U-bend R/(r+St) 3", expect_acceptance(u_bend_scene(0.016, 0.032, 0.144, false)));
}

TEST(SweepRings, SerpentineWithWallOfManyFaces) {
    print("serpentine 3 legs", expect_acceptance(serpentine_scene(0.016, 0.032, 3, 1.0, 0.3, false)));
    print("serpentine 4 legs, frames", expect_acceptance(serpentine_scene(0.016, 0.032, 4, 1.0, 0.3, true)));
}

TEST(SweepRings, WallFacesThatProjectIntoTheirRangesGiveTheSameRing) {
    // Bounded B-spline walls project a point past their end onto their end circle. The sweep
    // must still find the next face's foot point, not settle for that one.
    const Scene open = serpentine_scene(0.016, 0.032, 3, 1.0, 0.3, false);
    const Scene clamped = serpentine_scene(0.016, 0.032, 3, 1.0, 0.3, false, true);
    print("serpentine, clamped walls", expect_acceptance(clamped));
    HybridMesh a, b;
    sweep_tubes(a, open.tubes, open.lookup(), open.options());
    sweep_tubes(b, clamped.tubes, clamped.lookup(), clamped.options());
    ASSERT_EQ(a.point_count(), b.point_count());
    double moved = 0;
    for (index_t i = 0; i < a.point_count(); ++i) moved = std::max(moved, (eig(a.point(i)) - eig(b.point(i))).norm());
    EXPECT_LT(moved, 1e-9);
}

TEST(SweepRings, CrankshaftOilHoleMeetsTheJournalAtAnAngle) {
    // The paper's Example 3: an oil hole of diameter 12 in a journal of diameter 295, as geom's
    // paper-ex3 builds it (through the axis, 30 degrees from the surface normal), and slanting
    // across the journal's curvature, which tilts the host further under the ring.
    print("oil hole 30 deg along axis", expect_acceptance(oil_hole_scene(6, 12, 147.5, kPi / 6, true)));
    print("oil hole 40 deg along axis", expect_acceptance(oil_hole_scene(6, 12, 147.5, 40 * kPi / 180, true)));
    print("oil hole 30 deg across", expect_acceptance(oil_hole_scene(6, 12, 147.5, kPi / 6, false)));
    print("oil hole 40 deg across", expect_acceptance(oil_hole_scene(6, 12, 147.5, 40 * kPi / 180, false)));
}

TEST(SweepRings, ObliquePlaneAndConcaveBore) {
    print("oblique 40/30 deg", expect_acceptance(oblique_scene(0.02, 0.04, 40 * kPi / 180, 30 * kPi / 180, 0.5)));
}

// Every ring node moved 1e-4 r off the wall, radially and along the axis, alternately in and
// out.
void push_rings_off_the_wall(Scene& scene) {
    for (std::size_t t = 0; t < scene.tubes.size(); ++t) {
        TubeData& tube = scene.tubes[t];
        const double r = scene.specs[t].radius;
        for (auto [ring, station] : {std::pair{&tube.ring1, tube.stations.front()}, {&tube.ring2, tube.stations.back()}})
            for (std::size_t k = 0; k < ring->size(); ++k) {
                const V axis = eig(station.tangent), d = eig((*ring)[k]) - eig(station.centre);
                const V radial = (d - d.dot(axis) * axis).normalized();
                const double sign = k % 2 == 0 ? 1.0 : -1.0;
                (*ring)[k] = vec(eig((*ring)[k]) + sign * 1e-4 * r * (radial + 0.5 * axis));
            }
    }
}

// geom's end loops are B-rep edges whose 3D curve is only within the edge's tolerance of the
// wall/host intersection (3.6e-5 r off the wall measured on the builders' blocks). The sweep
// moves the ring nodes onto the intersection: the end stations' wall nodes then lie on the wall
// and the host within the same 1e-7 r as every other node.
TEST(SweepRings, EndRingsOffTheWallAreMovedOntoWallAndHost) {
    Scene oblique = oblique_scene(0.02, 0.04, 40 * kPi / 180, 30 * kPi / 180, 0.5);
    push_rings_off_the_wall(oblique);
    print("oblique, rings off the wall", expect_acceptance(oblique));
    Scene oil_hole = oil_hole_scene(6, 12, 147.5, kPi / 6, false);
    push_rings_off_the_wall(oil_hole);
    print("oil hole, rings off the wall", expect_acceptance(oil_hole));
}

TEST(SweepRings, LeftHandedRingsGiveValidHexesToo) {
    Scene scene;
    TubeSpec spec{0.02, 0.04, 0.12};
    spec.left_handed = true;
    spec.host1 = scene.plane(V(0, 0, 0), V(0, 0, -1));
    spec.host2 = scene.plane(V(0, 0, 1), V(0, 0, 1));
    Path path(V(0, 0, -spec.lead), V(0, 0, 1), V(1, 0, 0));
    path.straight(1 + 2 * spec.lead);
    scene.tube(path, spec);
    print("left-handed rings", expect_acceptance(scene));
}

TEST(SweepRings, ResultDescribesTheRing) {
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    HybridMesh mesh;
    mesh.add_point(9, 9, 9);  // existing content is kept; new ids follow it
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    ASSERT_EQ(result.rings.size(), 1u);
    const TubeRing& ring = result.rings[0];
    const index_t n = ring.circumferential, L = ring.radial_layers, m = ring.stations - 1;
    EXPECT_EQ(n, 8u);  // circumferential_count(0.02, 0.04)
    EXPECT_EQ(L, 2u);
    EXPECT_EQ(ring.first_node, 1u);
    EXPECT_EQ(mesh.point_count(), 1 + (m + 1) * (L + 1) * n);
    EXPECT_EQ(mesh.cell_count(CellKind::Hex), m * L * n);
    EXPECT_EQ(result.outer_quads.size(), 4u * m * n);
    EXPECT_EQ(result.wall_quads.size(), 4u * m * n);
    EXPECT_EQ(result.end_quads.size(), 4u * 2 * L * n);
    EXPECT_EQ(mesh.face_count(FaceKind::Quad), m * n + 2 * L * n);
    EXPECT_EQ(mesh.region_names.at(mesh.block(CellKind::Hex).region[0]), "hex_ring");
    EXPECT_EQ(mesh.surface_group_names.at(ring.wall_group), "pipe_1");
    EXPECT_EQ(mesh.surface_group_names.at(ring.host_group[0]), "face_1");
    EXPECT_EQ(mesh.surface_group_names.at(ring.host_group[1]), "face_2");
    EXPECT_EQ(mesh.block(FaceKind::Quad).group[ring.first_boundary_face], ring.wall_group);
    EXPECT_EQ(mesh.block(FaceKind::Quad).group[ring.first_boundary_face + m * n], ring.host_group[0]);
    // Outer quads about axial_aspect times longer along the pipe than around it.
    const double side = 2 * (0.02 + 0.04) * std::sin(kPi / n);
    EXPECT_NEAR(ring.axial_step / side, 1.5, 0.1);
    EXPECT_FALSE(ring.frame_fallback);
    EXPECT_NEAR(ring.twist, 0, 1e-9);
}

TEST(SweepRings, OuterPolygonsAreHolesOfTheHostFaces) {
    const Scene scene = oil_hole_scene(6, 12, 147.5, kPi / 6, false);
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    const TubeRing& ring = result.rings[0];
    for (int e = 0; e < 2; ++e) {
        const RingEnd& end = ring.ends[static_cast<std::size_t>(e)];
        ASSERT_EQ(end.outer_nodes.size(), ring.circumferential);
        EXPECT_EQ(end.host, e == 0 ? scene.tubes[0].host1 : scene.tubes[0].host2);
        const TestSurface& host = scene.surface(end.host);
        V centre = V::Zero();
        for (const Vec3& p : end.outer_xyz) centre += eig(p) / static_cast<double>(end.outer_xyz.size());
        V normal = V::Zero();
        for (std::size_t q = 0; q < end.outer_nodes.size(); ++q) {
            const V p = eig(mesh.point(end.outer_nodes[q]));
            EXPECT_EQ((p - eig(end.outer_xyz[q])).norm(), 0.0);
            EXPECT_LT((eig(host.point(end.outer_uv[q])) - p).norm(), 1e-9);
            // Distance St from the hole, measured across the axis.
            normal += (p - centre).cross(eig(end.outer_xyz[(q + 1) % end.outer_xyz.size()]) - centre);
        }
        for (std::size_t q = 1; q < end.outer_uv.size(); ++q)  // the hole sits on the journal's seam
            EXPECT_LT(std::abs(end.outer_uv[q].u - end.outer_uv[q - 1].u), kPi);
        // Clockwise seen from outside: the polygon's normal points into the solid.
        const Projection pr = host.project(vec(centre), std::nullopt);
        EXPECT_LT(normal.dot(eig(host.normal(pr.uv))), 0) << "end " << e;
        EXPECT_EQ(end.outer_nodes[0], ring.node(end.station, ring.radial_layers, 0));
    }
}

TEST(SweepRings, DefaultSweepSizeIsTheTubeDiameter) {
    const Scene scene = straight_scene(0.02, 0.04, 1.0);
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup());
    EXPECT_DOUBLE_EQ(result.rings[0].sweep_size, 0.04);
    SweepOptions options;
    options.sweep_size = 0.03;
    EXPECT_DOUBLE_EQ(sweep_tubes(mesh, scene.tubes, scene.lookup(), options).rings[0].sweep_size, 0.03);
}

TEST(SweepRings, BoundaryFacesCanBeLeftToTheCaller) {
    const Scene scene = straight_scene(0.02, 0.04, 0.5);
    HybridMesh mesh;
    SweepOptions options = scene.options();
    options.store_boundary_faces = false;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), options);
    EXPECT_EQ(mesh.face_count(FaceKind::Quad), 0u);
    EXPECT_EQ(result.rings[0].first_boundary_face, kNoIndex);
    // The caller adds all three kinds: the ring is closed and conforming.
    const index_t g = mesh.surface_group_id("all");
    for (const auto* quads : {&result.wall_quads, &result.end_quads})
        for (std::size_t q = 0; q < quads->size(); q += 4)
            mesh.add_face(FaceKind::Quad, std::span<const index_t>(quads->data() + q, 4), g);
    const CheckReport report = check_mesh(with_outer_quads(mesh, result));
    EXPECT_TRUE(report.ok()) << describe(report);
}

TEST(SweepRings, SeveralTubesAreNumberedInInputOrder) {
    Scene scene;
    TubeSpec spec{0.02, 0.04, 0.12};
    spec.host1 = scene.plane(V(0, 0, 0), V(0, 0, -1));
    spec.host2 = scene.plane(V(0, 0, 1), V(0, 0, 1));
    for (int t = 0; t < 3; ++t) {
        Path path(V(0.5 * t, 0, -spec.lead), V(0, 0, 1), V(1, 0, 0));
        path.straight(1 + 2 * spec.lead);
        scene.tube(path, spec);
    }
    HybridMesh mesh;
    const SweepResult result = sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
    ASSERT_EQ(result.rings.size(), 3u);
    for (index_t t = 1; t < 3; ++t) {
        const TubeRing& a = result.rings[t - 1];
        const TubeRing& b = result.rings[t];
        EXPECT_EQ(b.first_node, a.first_node + a.stations * (a.radial_layers + 1) * a.circumferential);
        EXPECT_EQ(b.first_hex, a.first_hex + a.hex_count);
        EXPECT_EQ(mesh.surface_group_names.at(b.wall_group), "pipe_" + std::to_string(t + 1));
        EXPECT_EQ(b.host_group, a.host_group);  // shared hosts share a group
    }
    const CheckReport report = check_mesh(with_outer_quads(mesh, result));
    EXPECT_TRUE(report.ok()) << describe(report);
}

}  // namespace
}  // namespace tubemesh::sweep_testing
