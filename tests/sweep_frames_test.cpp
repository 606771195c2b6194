// Rotation-minimising frames: no twist on planar bends and serpentines, exact on straight lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/sweep/frames.hpp"

namespace {

using tubemesh::Vec3;
using tubemesh::Frame;
using tubemesh::rotation_minimizing_frames;

struct Path {
    std::vector<Vec3> c, t;
};

// Half circle of radius R in the xy plane: a 180-degree bend.
Path half_circle(double R, int n) {
    Path p;
    for (int i = 0; i <= n; ++i) {
        const double a = std::numbers::pi * i / n;
        p.c.push_back({R * std::cos(a), R * std::sin(a), 0});
        p.t.push_back({-std::sin(a), std::cos(a), 0});
    }
    return p;
}

// Serpentine in the xy plane: straight legs joined by alternating half circles.
Path serpentine(int legs, double length, double R, int per_leg, int per_bend) {
    Path p;
    double y = 0;
    for (int leg = 0; leg < legs; ++leg) {
        const double dir = leg % 2 == 0 ? 1.0 : -1.0;
        const double x0 = dir > 0 ? 0 : length;
        for (int i = 0; i < per_leg; ++i) {
            p.c.push_back({x0 + dir * length * i / per_leg, y, 0});
            p.t.push_back({dir, 0, 0});
        }
        if (leg + 1 == legs) break;
        const double cx = dir > 0 ? length : 0, cy = y + R;
        for (int i = 0; i < per_bend; ++i) {
            const double a = std::numbers::pi * i / per_bend;  // from -pi/2 turning by pi
            const double s = dir > 0 ? 1.0 : -1.0;
            p.c.push_back({cx + s * R * std::sin(a), cy - R * std::cos(a), 0});
            p.t.push_back({s * std::cos(a), std::sin(a), 0});
        }
        y += 2 * R;
    }
    return p;
}

TEST(Frames, StraightLineKeepsTheInitialNormal) {
    std::vector<Vec3> c, t;
    for (int i = 0; i < 50; ++i) {
        c.push_back({0.1 * i, 0.2 * i, 0.3 * i});
        t.push_back({1, 2, 3});
    }
    const auto f = rotation_minimizing_frames(c, t, Vec3{0, 0, 1});
    const Vec3 n0 = f.front().normal;
    for (const Frame& fr : f) {
        EXPECT_NEAR(norm(fr.normal - n0), 0.0, 1e-14);
        EXPECT_NEAR(dot(fr.tangent, fr.normal), 0.0, 1e-15);
        EXPECT_NEAR(norm(fr.binormal), 1.0, 1e-15);
    }
}

// In a planar curve the rotation-minimising frame keeps the out-of-plane normal fixed, and an
// in-plane normal stays in-plane: the circumferential node at angle 0 stays on the same side.
TEST(Frames, HalfCircleBendHasNoTwist) {
    const Path p = half_circle(3.0, 200);
    const auto up = rotation_minimizing_frames(p.c, p.t, Vec3{0, 0, 1});
    for (const Frame& f : up) EXPECT_NEAR(f.normal.z, 1.0, 1e-12);
    const auto in_plane = rotation_minimizing_frames(p.c, p.t, Vec3{-1, 0, 0});
    for (std::size_t i = 0; i < in_plane.size(); ++i) {
        EXPECT_NEAR(in_plane[i].normal.z, 0.0, 1e-12);
        // Pointing to the bend's centre (inwards) all the way.
        EXPECT_LT(dot(in_plane[i].normal, p.c[i]), 0.0);
    }
}

TEST(Frames, SerpentineHasNoTwistEndToEnd) {
    const Path p = serpentine(6, 10.0, 0.75, 40, 30);
    const auto f = rotation_minimizing_frames(p.c, p.t, Vec3{0, 0, 1});
    double worst = 0;
    for (const Frame& fr : f) worst = std::max(worst, std::abs(1.0 - fr.normal.z));
    EXPECT_LT(worst, 1e-12);
}

TEST(Frames, HelixFrameDoesNotRotateAboutTheTangent) {
    // A helix has torsion, so the Frenet frame spins about the tangent; the rotation-minimising
    // frame must not: its normal changes only along the tangent (dN/ds = -k1 T).
    std::vector<Vec3> c, t;
    const double a = 1.0, b = 0.3;
    for (int i = 0; i <= 2000; ++i) {
        const double s = 4 * std::numbers::pi * i / 2000;
        c.push_back({a * std::cos(s), a * std::sin(s), b * s});
        t.push_back({-a * std::sin(s), a * std::cos(s), b});
    }
    const auto f = rotation_minimizing_frames(c, t, Vec3{1, 0, 0});
    for (std::size_t i = 1; i < f.size(); ++i) {
        EXPECT_NEAR(dot(f[i].tangent, f[i].normal), 0.0, 1e-13);
        EXPECT_LT(norm(f[i].normal - f[i - 1].normal), 0.01);
    }
    // Bishop frame rotation about the tangent is zero: d(normal)/ds is parallel to the tangent.
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
        const Vec3 dn = f[i + 1].normal - f[i - 1].normal;
        EXPECT_LT(std::abs(dot(dn, f[i].binormal)), 1e-6);
    }
}

TEST(Frames, BadInputIsAnError) {
    std::vector<Vec3> c{{0, 0, 0}, {0, 0, 0}}, t{{1, 0, 0}, {1, 0, 0}};
    EXPECT_THROW(rotation_minimizing_frames(c, t, Vec3{0, 1, 0}), tubemesh::Error);
    c[1] = {1, 0, 0};
    EXPECT_THROW(rotation_minimizing_frames(c, t, Vec3{1, 0, 0}), tubemesh::Error);
    t[1] = {0, 0, 0};
    EXPECT_THROW(rotation_minimizing_frames(c, t, Vec3{0, 1, 0}), tubemesh::Error);
    EXPECT_THROW(rotation_minimizing_frames(std::span(c).first(1), std::span(t).first(1), Vec3{0, 1, 0}),
                 tubemesh::Error);
}

TEST(Frames, SignedAngle) {
    EXPECT_NEAR(tubemesh::signed_angle({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), std::numbers::pi / 2, 1e-15);
    EXPECT_NEAR(tubemesh::signed_angle({1, 0, 0}, {0, -1, 0}, {0, 0, 1}), -std::numbers::pi / 2, 1e-15);
    const Vec3 t{1, 2, 3};
    EXPECT_NEAR(dot(tubemesh::any_orthogonal(normalized(t)), t), 0.0, 1e-15);
}

}  // namespace
