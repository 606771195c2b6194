// Foot points on a wall of several faces: the face the foot lies on, not merely the nearest
// surface, and not a clamped foot at the end of the face the node came from.
#include <gtest/gtest.h>

#include "engine/core/types.hpp"
#include "engine/sweep/wall_projection.hpp"
#include "tests/support/sweep_surfaces.hpp"

namespace tubemesh::sweep_testing {
namespace {

constexpr double kR = 0.02;

// Two collinear pieces of a straight wall along z: [0, 1] and [1, 2].
struct TwoPieces {
    explicit TwoPieces(bool clamped)
        : first(1, V(0, 0, 0), V(0, 0, 1), V(1, 0, 0), kR, {0, 2 * kPi, true, 2 * kPi}, {0, 1}, false, clamped),
          second(2, V(0, 0, 1), V(0, 0, 1), V(1, 0, 0), kR, {0, 2 * kPi, true, 2 * kPi}, {0, 1}, false, clamped),
          wall({&first, &second}, kR) {}
    CylinderFace first, second;
    sweep::WallProjection wall;
};

TEST(SweepWallProjection, StaysOnItsFaceWhileTheFootIsOnIt) {
    TwoPieces w(false);
    sweep::WallCursor cursor{0, {0, 0.5}};
    const sweep::WallFoot foot = w.wall.project({kR * 1.001, 0, 0.7}, cursor);
    EXPECT_EQ(cursor.face, 0);
    EXPECT_NEAR(foot.point.z, 0.7, 1e-15);
    EXPECT_NEAR(foot.distance, 0.001 * kR, 1e-15);
}

TEST(SweepWallProjection, MovesToTheNextFacePastTheEnd) {
    for (bool clamped : {false, true}) {
        TwoPieces w(clamped);
        sweep::WallCursor cursor{0, {0, 0.99}};
        // Just past the first piece's end, well within the tolerance a clamped foot would need
        // to be trusted at a quarter radius.
        const sweep::WallFoot foot = w.wall.project({kR * 1.0001, 0, 1 + 0.1 * kR}, cursor);
        EXPECT_EQ(cursor.face, 1) << (clamped ? "clamped" : "open");
        EXPECT_NEAR(foot.point.z, 1 + 0.1 * kR, 1e-15) << (clamped ? "clamped" : "open");
    }
}

TEST(SweepWallProjection, FindsTheFaceWithoutACursor) {
    TwoPieces w(true);
    sweep::WallCursor cursor;
    const sweep::WallFoot foot = w.wall.project({0, -kR, 1.6}, cursor);
    EXPECT_EQ(cursor.face, 1);
    EXPECT_NEAR(foot.point.z, 1.6, 1e-15);
}

TEST(SweepWallProjection, RefusesAPointFarFromTheWall) {
    TwoPieces w(false);
    sweep::WallCursor cursor;
    EXPECT_THROW(w.wall.project({0, 0, 0.5}, cursor), Error);  // on the axis: no foot point
    EXPECT_THROW(w.wall.project({2 * kR, 0, 0.5}, cursor), Error);
}

}  // namespace
}  // namespace tubemesh::sweep_testing
