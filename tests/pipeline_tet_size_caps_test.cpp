// TetSizeCaps (engine/sizing/tet_size_caps.hpp) on hand-made meshes: one ring outer quad
// and surface triangles at known distances, measured against the volume size computed here
// from its definition, h(x) = min(S, q + max(G - 1, g)|x - c|) for the quad's centroid c and
// mean edge q.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "engine/sizing/tet_size_caps.hpp"

namespace {

using namespace tubemesh;

constexpr double kS = 3.0, kG = 1.6, kGrowth = 0.25;

// A 0.1 x 0.1 outer quad in the plane z = 0 with its centroid at the origin: q = 0.1.
struct Scene {
    HybridMesh mesh;
    std::vector<index_t> quad;
    index_t group = 0;

    Scene() {
        for (auto [x, y] : {std::array{-0.05, -0.05}, {0.05, -0.05}, {0.05, 0.05}, {-0.05, 0.05}})
            quad.push_back(mesh.add_point(x, y, 0));
        group = mesh.surface_group_id("face_1");
    }
    // An equilateral triangle of edge `a` in the plane y = `y`, centred on (0, y, 0).
    void triangle(double y, double a) {
        const double r = a / std::sqrt(3.0);  // circumradius
        std::array<index_t, 3> t{};
        for (int k = 0; k < 3; ++k) {
            const double phi = 2 * std::numbers::pi * k / 3;
            t[k] = mesh.add_point(r * std::cos(phi), y, r * std::sin(phi));
        }
        mesh.add_face(FaceKind::Tri, t, group);
    }
};

double volume_size(double distance) { return std::min(kS, 0.1 + (kG - 1) * distance); }

std::vector<SizeSource> caps(const Scene& s, index_t first, double gradation = kG,
                             std::span<const index_t> quads = {}) {
    return TetSizeCaps(s.mesh, quads.empty() ? std::span<const index_t>(s.quad) : quads, kS, gradation, kGrowth)
        .caps(s.mesh, first);
}

TEST(TetSizeCaps, CapsOnlyTrianglesTooLargeForTheTetsBesideThem) {
    Scene s;
    s.triangle(0.5, 2.0);   // h = 0.4: 2.0 > 2 h, capped at 1.25 h
    s.triangle(10.0, 2.0);  // h = S: fine
    s.triangle(0.5, 0.7);   // 0.7 < 2 h: fine
    s.triangle(-1.0, 1.5);  // h = 0.7: 1.5 > 1.4, capped
    const std::vector<SizeSource> c = caps(s, 0);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_NEAR(c[0].point.y, 0.5, 1e-12);
    EXPECT_NEAR(c[0].point.x, 0.0, 1e-12);
    EXPECT_NEAR(c[0].size, kCapped * volume_size(0.5), 1e-12);
    EXPECT_NEAR(c[1].point.y, -1.0, 1e-12);
    EXPECT_NEAR(c[1].size, kCapped * volume_size(1.0), 1e-12);
}

TEST(TetSizeCaps, OnlyTrianglesFromTheFirstOneOn) {
    Scene s;
    s.triangle(0.5, 2.0);  // too large, but before first_triangle
    s.triangle(0.5, 0.5);
    EXPECT_TRUE(caps(s, 1).empty());
    EXPECT_EQ(caps(s, 0).size(), 1u);
}

TEST(TetSizeCaps, TheGradationSetsTheVolumeSize) {
    Scene s;
    s.triangle(1.0, 1.5);  // G 1.6: h 0.7, capped; G 2: h 1.1, fine
    EXPECT_EQ(caps(s, 0, 1.6).size(), 1u);
    EXPECT_TRUE(caps(s, 0, 2.0).empty());
    // Below 1 + g the surface's own growth g bounds the volume size's: at G 1 the quad asks for
    // 0.1 + 0.25 d, not 0.1 everywhere (which would cap every triangle of a block).
    Scene far;
    far.triangle(2.0, 1.0);  // h = 0.6 at G 1 (0.1 + 0.25 · 2): 1.0 < 1.2, fine
    far.triangle(1.0, 1.0);  // h = 0.35: capped
    const std::vector<SizeSource> c = caps(far, 0, 1.0);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].size, kCapped * (0.1 + kGrowth * 1.0), 1e-12);
}

TEST(TetSizeCaps, NoQuadsNoCapsAndBadOptionsAreErrors) {
    Scene s;
    s.triangle(0.5, 2.0);
    EXPECT_TRUE(TetSizeCaps(s.mesh, {}, kS, kG, kGrowth).caps(s.mesh, 0).empty());
    EXPECT_THROW(TetSizeCaps(s.mesh, s.quad, kS, 0.9, kGrowth), Error);
    EXPECT_THROW(TetSizeCaps(s.mesh, s.quad, kS, kG, 0.0), Error);
}

// Triangles left too large warn of flat tets only where that is so: before the tets, that they
// may be; once made, only when the worst is poor (the serpentine lift's 0.373 is not).
TEST(TetSizeCaps, TooLargeLeftWarnsOnlyOfFlatTets) {
    EXPECT_EQ(too_large_warning(0, 2, std::nullopt), "");
    EXPECT_EQ(too_large_warning(0, 2, 0.01), "");
    const std::string before = too_large_warning(4, 2, std::nullopt);
    EXPECT_NE(before.find("4 triangles are still more than 2 times the tet size"), std::string::npos) << before;
    EXPECT_NE(before.find("may be flat"), std::string::npos) << before;
    EXPECT_EQ(too_large_warning(4, 2, 0.373), "");
    EXPECT_EQ(too_large_warning(4, 2, kPoorTet), "");
    const std::string flat = too_large_warning(4, 2, 0.05);
    EXPECT_NE(flat.find("after 2 passes and the worst tet's collapse is 0.05"), std::string::npos) << flat;
    EXPECT_NE(flat.find("--size"), std::string::npos) << flat;
}

}  // namespace
