#include "geom/builders/serpentine.hpp"

#include <cmath>
#include <sstream>

#include "engine/core/types.hpp"

namespace tubemesh::geom {

namespace {

struct Side {
    int axis;  // 0 = x, 1 = y
    bool plus;
};

Side parse_side(const std::string& s, const char* what) {
    if (s == "x-") return {0, false};
    if (s == "x+") return {0, true};
    if (s == "y-") return {1, false};
    if (s == "y+") return {1, true};
    throw Error(std::string("serpentine ") + what + " '" + s + "' is not a side face: use x-, x+, y- or y+");
}

}  // namespace

BlockSpec serpentine_spec(const SerpentineParams& p, const std::string& name) {
    const Side in = parse_side(p.inlet, "inlet"), out = parse_side(p.outlet, "outlet");
    if (in.axis != out.axis)
        throw Error("serpentine inlet " + p.inlet + " and outlet " + p.outlet +
                    " must be on the same face or on opposite faces");
    if (!(p.size.x > 0 && p.size.y > 0 && p.size.z > 0 && p.diameter > 0 && p.spacing > 0))
        throw Error("serpentine size, diameter and spacing must be positive");
    if (p.bend_radius > p.spacing / 2 * (1 + 1e-12))
        throw Error("serpentine bend radius " + std::to_string(p.bend_radius) + " must be at most half the spacing (" +
                    std::to_string(p.spacing / 2) + ")");

    const double along = in.axis == 0 ? p.size.x : p.size.y;   // run direction
    const double across = in.axis == 0 ? p.size.y : p.size.x;  // runs spread this way
    const double fitting = std::floor((across - p.spacing) / p.spacing + 1e-9) + 1;
    // Far more than any dam lift (the preset has 9); also keeps the count an int.
    constexpr int kMaxRuns = 1000;
    if (fitting > kMaxRuns)
        throw Error("serpentine: " + std::to_string(across) + " across at a spacing of " + std::to_string(p.spacing) +
                    " makes more than " + std::to_string(kMaxRuns) + " runs; give a larger spacing or a smaller lift");
    int runs = static_cast<int>(fitting);
    const bool same_face = in.plus == out.plus;
    if ((runs % 2 == 0) != same_face) --runs;
    if (runs < (same_face ? 2 : 1))
        throw Error("serpentine: no room for the runs: the lift is " + std::to_string(across) + " across for a spacing of " +
                    std::to_string(p.spacing));
    if (p.end_margin + p.bend_radius >= along / 2)
        throw Error("serpentine: end margin and bend radius leave no straight run along the lift");

    const double offset = (across - (runs - 1) * p.spacing) / 2;
    const double radius = p.diameter / 2;
    if (p.height_radii != 0 && !(p.height_radii > 1 && (p.height_radii + 1) * radius < p.size.z)) {
        std::ostringstream s;
        s << "serpentine: the pipe's centre " << p.height_radii
          << " radii above the lift's bottom: give more than 1 (the pipe would cut the bottom) and less than "
          << p.size.z / radius - 1 << " (the pipe would cut the top)";
        throw Error(s.str());
    }
    const double z = p.height_radii > 0 ? p.height_radii * radius : p.size.z / 2;
    // s runs from the inlet face into the lift; a maps it back to the coordinate.
    auto point = [&](double s, int run) {
        const double a = in.plus ? along - s : s;
        const double b = offset + run * p.spacing;
        return in.axis == 0 ? Vec3{a, b, z} : Vec3{b, a, z};
    };
    PipeSpec pipe;
    pipe.kind = PathKind::Polyline;
    pipe.diameter = p.diameter;
    pipe.bend_radius = p.bend_radius;
    pipe.points.push_back(point(0, 0));
    for (int k = 0; k + 1 < runs; ++k) {
        const double turn = k % 2 == 0 ? along - p.end_margin : p.end_margin;
        pipe.points.push_back(point(turn, k));
        pipe.points.push_back(point(turn, k + 1));
    }
    pipe.points.push_back(point(runs % 2 == 1 ? along : 0, runs - 1));

    BlockSpec spec;
    spec.name = name;
    spec.length_unit = p.length_unit;
    spec.host.kind = HostSpec::Kind::Box;
    spec.host.size = p.size;
    spec.pipes.push_back(std::move(pipe));
    return spec;
}

}  // namespace tubemesh::geom
