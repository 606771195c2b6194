// The clearance diagnosis's findings (geom/sizing/geometry_diagnosis.hpp) on measured distances
// as OpenCASCADE gives them: walls that touch measure a few 1e-13 either side of zero, and a
// warning says 0, never a negative distance or thickness; which of two close pipes loses its ring.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geom/sizing/geometry_diagnosis.hpp"

namespace {

using namespace tubemesh;

geom::TubeSearch two_pipes() {
    geom::TubeSearch found;
    for (int face : {6, 8}) {
        geom::TubeInfo t;
        t.faces = {face};
        t.radius_min = t.radius_max = 0.1;
        t.length = face == 6 ? 2 : 1;
        found.tubes.push_back(t);
    }
    return found;
}

std::string warning_of(const geom::SizePlan& plan, int expected_tube) {
    geom::RingDrop drop;
    EXPECT_EQ(geom::tube_without_room(two_pipes(), plan, geom::kThinnestSharedRing, geom::kThinnestSharedRing, drop), expected_tube);
    EXPECT_NE(drop.warning.find("meshed with tetrahedra"), std::string::npos) << drop.warning;
    return drop.warning;
}

TEST(GeometryDiagnosis, TouchingPipesAreZeroApartNotNegative) {
    geom::SizePlan plan;
    plan.dcb = INFINITY;
    plan.rc = INFINITY;
    plan.dc = -4.7e-13;
    plan.dc_tube_a = 0;
    plan.dc_tube_b = 1;
    // Neither ring would fit against the other's wall: the shorter pipe (face 8) goes.
    const std::string message = warning_of(plan, 1);
    EXPECT_NE(message.find("the pipe of wall face 8 comes within 0 of the pipe of wall face 6"), std::string::npos)
        << message;
    EXPECT_NE(message.find("under 0 thick"), std::string::npos) << message;
    EXPECT_NE(message.find("they touch"), std::string::npos) << message;
    EXPECT_EQ(message.find("-"), message.find("- they touch")) << message;
    plan.dc = 5.83e-16;  // the other side of zero: they touch all the same
    const std::string above = warning_of(plan, 1);
    EXPECT_NE(above.find("comes within 0 of"), std::string::npos) << above;
}

TEST(GeometryDiagnosis, OfTwoClosePipesTheOneKeptHasRoomAgainstTheOther) {
    geom::SizePlan plan;
    plan.dcb = INFINITY;
    plan.rc = INFINITY;
    plan.dc_tube_a = 0;
    plan.dc_tube_b = 1;
    plan.dc = 0.035;  // 0.35 r: room for 0.083 r between two rings, 0.11 r for one against a wall
    EXPECT_EQ(warning_of(plan, 1).find("the pipe of wall face 8 comes within"), 0u);
    plan.dc = 0.05;  // far enough for both rings
    geom::RingDrop drop;
    EXPECT_EQ(geom::tube_without_room(two_pipes(), plan, geom::kThinnestSharedRing, geom::kThinnestSharedRing, drop), -1);
}

TEST(GeometryDiagnosis, PipeTouchingAFaceIsZeroFromItNotNegative) {
    geom::SizePlan plan;
    plan.dc = INFINITY;
    plan.rc = INFINITY;
    plan.dcb = -3e-13;
    plan.dcb_tube = 0;
    plan.dcb_face = 4;
    const std::string message = warning_of(plan, 0);
    EXPECT_NE(message.find("passes 0 from face 4"), std::string::npos) << message;
    EXPECT_NE(message.find("under 0 thick"), std::string::npos) << message;
}

TEST(GeometryDiagnosis, HoleTouchingAFaceIsZeroFromItNotNegative) {
    geom::HoleClearance h;
    h.hole_faces = {7};
    h.face = 3;
    h.distance = -2e-13;
    h.radius = 0.25;
    std::string cause;
    const std::vector<std::string> warnings = geom::narrow_gap_warnings({h}, cause);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("passes 0 from face 3"), std::string::npos) << warnings[0];
    EXPECT_EQ(cause, "a gap too narrow for sound tets (the hole of faces 7 passes 0 from face 3, 0 of its radius)");
}

}  // namespace
