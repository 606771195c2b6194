#pragma once
// The distances the sizing rules need (paper §2): Dc between tube walls and Dcb from a tube
// wall to the boundary faces that are neither its hosts nor a tube's wall.
//
// A circular tube is the set of points within r of its centre line, so the distance from its
// wall to anything outside it is the distance to the centre line minus r. Distances are taken
// to the tubes' centre-line polylines (TubeInfo::centre_line) minus r_max: exact up to the
// polylines' 1%-of-r chord error, and far cheaper than BRepExtrema between B-spline walls.
#include <limits>
#include <vector>

#include "geom/model/model.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

struct Clearances {
    double dc = std::numeric_limits<double>::infinity();
    int dc_tube_a = -1, dc_tube_b = -1;  // 0-based tube indices attaining dc
    double dcb = std::numeric_limits<double>::infinity();
    int dcb_tube = -1;  // 0-based tube index attaining dcb
    int dcb_face = 0;   // the face it is closest to
};

Clearances measure_clearances(const Model& model, const std::vector<TubeInfo>& tubes);

// A hole that is not a tube (a rejected face group) whose faces are cylinders or tori, with
// the faces it does not touch whose boxes come within max(its radius, `size`) of its own: the
// faces a narrow gap can lie between (the diagnosis looks within the radius, the gap sizes
// within S). Found once per run for both.
struct HoleGroup {
    std::vector<int> faces;       // the rejected group
    double radius = 0;            // its smallest cylinder or torus (minor) radius, or TubeRejection::radius
    std::vector<int> near_faces;  // not in the group, sharing no edge with it, boxes within reach
};
std::vector<HoleGroup> hole_groups(const Model& model, const TubeSearch& tubes, double size);

// The closest each hole group comes to one of its near faces.
struct HoleClearance {
    std::vector<int> hole_faces;
    double radius = 0;
    double distance = std::numeric_limits<double>::infinity();
    int face = 0;  // the face attaining it
};
std::vector<HoleClearance> measure_hole_clearances(const Model& model, const std::vector<HoleGroup>& holes);

// Diagonal of the solid's bounding box, for the default S: BRepBndLib::Add over the faces
// that are no tube's wall. Not Model::bounds(): its optimal box is slow on long B-spline pipe
// walls. Not the walls either: a B-spline wall's control polygon inflates a plain box, and
// the walls lie inside the box of the other faces anyway.
double box_diagonal(const Model& model, const std::vector<TubeInfo>& tubes);
// That box itself (all zero for a model without faces).
BoundingBox non_wall_box(const Model& model, const std::vector<TubeInfo>& tubes);

// Smallest distance between two polylines (each at least one point).
double polyline_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace tubemesh::geom
