#pragma once
// Plain-data description of a solid with tubular holes: a host (box or cylinder) and the centre
// lines and diameters of the pipes cut through it. Presets, random blocks and JSON specs all
// produce a BlockSpec; build_block turns it into a geom::Model.
#include <optional>
#include <string>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"  // tubemesh::Vec3

namespace tubemesh::geom {

struct HostSpec {
    enum class Kind { Box, Cylinder };
    Kind kind = Kind::Box;
    Vec3 size{1, 1, 1};    // Box: from the origin to `size`
    double diameter = 1;   // Cylinder: axis along z through x = y = 0, from z = 0 to z = length
    double length = 1;
};

enum class PathKind {
    Line,      // points: two points on the host boundary (or anywhere along the line)
    Arc,       // points: start, a point on the arc, end (start and end on the host boundary)
    Polyline,  // points: start, corners, end; corners rounded with bend_radius
    Spline,    // points: the curve passes through them (C2 interpolation)
    Bspline,   // points: control points of a cubic B-spline (passes through the first and last only)
};

struct PipeSpec {
    PathKind kind = PathKind::Spline;
    std::vector<Vec3> points;
    double diameter = 0.1;
    double bend_radius = 0;  // Polyline: corner radius, > diameter; ignored otherwise
    // Spline only: directions at the first and last point. Default: the host's normal when the
    // point lies on a face (the pipe meets the face at a right angle), else the natural end.
    std::optional<Vec3> start_tangent, end_tangent;
    // Line only: the hole ends at the second point, inside the host (a drilled blind hole).
    bool blind = false;
};

// Every path is extended past its first and last point along its end directions, so that the
// cut goes through the host and the pipe ends on its faces; points should lie on the boundary.
struct BlockSpec {
    std::string name;                       // preset name, "seed 7", or the spec file
    std::string length_unit = "model units"; // a label for reports and the STEP file ("metre", ...)
    HostSpec host;
    std::vector<PipeSpec> pipes;
    // false: skip the clearance checks and build what the pipes make even when they cross,
    // touch or graze the boundary (test input for the mesher's own diagnosis).
    bool check_clearance = true;
};

// What a builder knows about its result, for reports and tests.
struct BlockInfo {
    std::string name;
    std::string length_unit;
    int pipe_count = 0;
    std::vector<double> pipe_diameters;
    double host_volume = 0;
    // Host volume minus the pipes' volume where that is known in closed form: straight pipes in
    // a box (pi r^2 times the axis length inside) and arcs whose end planes contain the arc's axis
    // (a torus section, Pappus). Empty when any pipe is curved otherwise.
    std::optional<double> expected_volume;
    double volume = 0;  // of the built solid, by OpenCASCADE's volume integration
};

}  // namespace tubemesh::geom
