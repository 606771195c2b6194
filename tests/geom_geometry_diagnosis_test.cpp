// The clearance diagnosis's messages (geom/sizing/geometry_diagnosis.hpp) on measured distances
// as OpenCASCADE gives them: walls that touch measure a few 1e-13 either side of zero, and a
// message says 0, never a negative distance or thickness.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geom/sizing/geometry_diagnosis.hpp"
#include "tests/support/error_of.hpp"

namespace {

using namespace tubemesh;

geom::TubeSearch two_pipes() {
    geom::TubeSearch found;
    for (int face : {6, 8}) {
        geom::TubeInfo t;
        t.faces = {face};
        t.radius_min = t.radius_max = 0.1;
        found.tubes.push_back(t);
    }
    return found;
}

TEST(GeometryDiagnosis, TouchingPipesAreZeroApartNotNegative) {
    geom::SizePlan plan;
    plan.dcb = INFINITY;
    plan.dc = -4.7e-13;
    plan.dc_tube_a = 0;
    plan.dc_tube_b = 1;
    const std::string message = tubemesh::testing::error_of([&] { geom::diagnose_clearances(two_pipes(), plan); });
    EXPECT_NE(message.find("come within 0 of each other"), std::string::npos) << message;
    EXPECT_NE(message.find("under 0 thick"), std::string::npos) << message;
    EXPECT_NE(message.find("they touch"), std::string::npos) << message;
    EXPECT_EQ(message.find("-"), message.find("- they touch")) << message;
    plan.dc = 5.83e-16;  // the other side of zero: they touch all the same
    const std::string above = tubemesh::testing::error_of([&] { geom::diagnose_clearances(two_pipes(), plan); });
    EXPECT_NE(above.find("come within 0 of each other"), std::string::npos) << above;
}

TEST(GeometryDiagnosis, PipeTouchingAFaceIsZeroFromItNotNegative) {
    geom::SizePlan plan;
    plan.dc = INFINITY;
    plan.dcb = -3e-13;
    plan.dcb_tube = 0;
    plan.dcb_face = 4;
    const std::string message = tubemesh::testing::error_of([&] { geom::diagnose_clearances(two_pipes(), plan); });
    EXPECT_NE(message.find("passes 0 from face 4"), std::string::npos) << message;
    EXPECT_NE(message.find("under 0 thick"), std::string::npos) << message;
}

TEST(GeometryDiagnosis, HoleTouchingAFaceIsZeroFromItNotNegative) {
    geom::HoleClearance h;
    h.hole_faces = {7};
    h.face = 3;
    h.distance = -2e-13;
    h.radius = 0.25;
    const std::string message = tubemesh::testing::error_of([&] { geom::diagnose_hole_clearances({h}); });
    EXPECT_NE(message.find("passes 0 from face 3"), std::string::npos) << message;
}

}  // namespace
