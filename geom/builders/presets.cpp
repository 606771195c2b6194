#include "geom/builders/presets.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/types.hpp"
#include "geom/builders/serpentine.hpp"

namespace tubemesh::geom {

namespace {

constexpr double kPi = std::numbers::pi;

BlockSpec box(std::string name, Vec3 size, std::string unit) {
    BlockSpec spec;
    spec.name = std::move(name);
    spec.length_unit = std::move(unit);
    spec.host.kind = HostSpec::Kind::Box;
    spec.host.size = size;
    return spec;
}

PipeSpec pipe(PathKind kind, double diameter, std::vector<Vec3> points) {
    PipeSpec p;
    p.kind = kind;
    p.diameter = diameter;
    p.points = std::move(points);
    return p;
}

// Paper §6.1: a 15 x 25 x 4 dam block with one cooling pipe of diameter 0.04, here a gentle
// S-curve at mid-height from the y = 0 face to the y = 25 face, square to both.
BlockSpec paper_ex1() {
    BlockSpec s = box("paper-ex1", {15, 25, 4}, "metre");
    s.pipes.push_back(pipe(PathKind::Spline, 0.04, {{5, 0, 2}, {6.2, 8, 2}, {8.8, 17, 2}, {10, 25, 2}}));
    return s;
}

// Paper §6.2: an 11 x 12 x 11 block with 4 curved holes of diameter 0.2, open at both ends:
// across the block, around a corner, a U-bend back to its own face, and a rising bend. The
// paper's rings (Table 1: 320 hexes, 160 pyramids, two layers, so about 40 steps of about S = 1.1
// along four holes some 11 long) cannot follow a bend much tighter than their step, so no bend
// here is tighter than the U-bend's 0.64 (the rising bend's is 1.7).
BlockSpec paper_ex2() {
    BlockSpec s = box("paper-ex2", {11, 12, 11}, "model units");
    s.pipes.push_back(pipe(PathKind::Spline, 0.2, {{0, 3, 3}, {3, 3.6, 4.2}, {7, 2.6, 6.2}, {11, 4, 7.5}}));
    s.pipes.push_back(pipe(PathKind::Spline, 0.2, {{8.5, 0, 3}, {8.6, 3, 4}, {9, 6, 7}, {8.5, 7.5, 11}}));
    s.pipes.push_back(pipe(PathKind::Spline, 0.2, {{2.5, 12, 8}, {2.8, 9, 8.2}, {4.5, 7.2, 8.4}, {6.2, 9, 8.6}, {6.5, 12, 8.8}}));
    s.pipes.push_back(pipe(PathKind::Spline, 0.2, {{4, 8, 0}, {4.4, 8.2, 1.5}, {5.5, 8.7, 3}, {7.5, 9.2, 3.8}, {11, 9.5, 4}}));
    return s;
}

// Paper §6.3: a main journal of a large crankshaft, diameter 295, with an oil hole of
// diameter 12 drilled straight through at 30 degrees to the cross-section. It passes through
// the axis in the vertical plane at 45 degrees, so both ends meet the curved surface at 30
// degrees from its normal, away from the cylinder's seam (the +x side).
BlockSpec paper_ex3() {
    BlockSpec s;
    s.name = "paper-ex3";
    s.length_unit = "millimetre";
    s.host.kind = HostSpec::Kind::Cylinder;
    s.host.diameter = 295;
    s.host.length = 300;
    const double tilt = kPi / 6, azimuth = kPi / 4, R = 295.0 / 2;
    const Vec3 d{std::cos(tilt) * std::cos(azimuth), std::cos(tilt) * std::sin(azimuth), std::sin(tilt)};
    const double t = R / std::cos(tilt);  // where the line meets the cylinder
    const Vec3 c{0, 0, 150};
    s.pipes.push_back(pipe(PathKind::Line, 12, {{c.x - t * d.x, c.y - t * d.y, c.z - t * d.z},
                                                {c.x + t * d.x, c.y + t * d.y, c.z + t * d.z}}));
    return s;
}

BlockSpec straight_pipe() {
    BlockSpec s = box("straight-pipe", {4, 3, 2}, "metre");
    s.pipes.push_back(pipe(PathKind::Line, 0.1, {{0, 1.5, 1}, {4, 1.5, 1}}));
    return s;
}

// A line meeting both faces at about 10 degrees off square: still a closed-form volume.
BlockSpec oblique_pipe() {
    BlockSpec s = box("oblique-pipe", {4, 3, 2}, "metre");
    s.pipes.push_back(pipe(PathKind::Line, 0.1, {{0, 1.2, 0.8}, {4, 1.8, 1.2}}));
    return s;
}

// A quarter torus around the block's z edge at the origin: from the y = 0 face to the x = 0
// face, both end planes through the arc's axis, so its volume is pi r^2 R pi / 2.
BlockSpec arc_pipe() {
    BlockSpec s = box("arc-pipe", {4, 4, 2}, "metre");
    const double R = 2.5;
    s.pipes.push_back(pipe(PathKind::Arc, 0.1, {{R, 0, 1}, {R * std::cos(kPi / 4), R * std::sin(kPi / 4), 1}, {0, R, 1}}));
    return s;
}

// Two straight pipes and one arc: closed-form volume with several tools in one boolean.
BlockSpec three_pipes() {
    BlockSpec s = box("three-pipes", {6, 5, 3}, "metre");
    s.pipes.push_back(pipe(PathKind::Line, 0.12, {{0, 3.5, 1}, {6, 3.5, 1}}));
    s.pipes.push_back(pipe(PathKind::Line, 0.08, {{4.5, 0, 2.2}, {4.5, 5, 2.2}}));
    const double R = 2;
    s.pipes.push_back(pipe(PathKind::Arc, 0.1, {{R, 0, 1.5}, {R * std::cos(kPi / 4), R * std::sin(kPi / 4), 1.5}, {0, R, 1.5}}));
    return s;
}

// A polyline with rounded corners, not in one plane: entering through x = 0, leaving through z = 3.
BlockSpec bent_pipe() {
    BlockSpec s = box("bent-pipe", {6, 5, 3}, "metre");
    PipeSpec p = pipe(PathKind::Polyline, 0.1, {{0, 1, 1}, {3, 1, 1}, {3, 3.5, 1.5}, {4.5, 3.5, 1.5}, {4.5, 3.5, 3}});
    p.bend_radius = 0.4;
    s.pipes.push_back(p);
    return s;
}

// A U-bend: both ends on the z = 0 face, as a cubic B-spline from control points.
BlockSpec u_bend() {
    BlockSpec s = box("u-bend", {5, 4, 3}, "metre");
    s.pipes.push_back(pipe(PathKind::Bspline, 0.1, {{1.5, 2, 0}, {1.5, 2, 1}, {1.5, 2, 2.2}, {3.5, 2, 2.2}, {3.5, 2, 1}, {3.5, 2, 0}}));
    return s;
}

struct Entry {
    PresetInfo info;
    BlockSpec (*make)();
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> list = {
        {{"paper-ex1", "dam block 15 x 25 x 4 m, one gently curved cooling pipe of diameter 0.04 (paper 6.1)"}, paper_ex1},
        {{"paper-ex2", "block 11 x 12 x 11, four curved holes of diameter 0.2 (paper 6.2)"}, paper_ex2},
        {{"paper-ex3", "crankshaft journal, diameter 295 mm, length 300, inclined oil hole of diameter 12 (paper 6.3)"}, paper_ex3},
        {{"serpentine-lift", "dam lift 20 x 15 x 3 m, serpentine cooling pipe of diameter 0.032, runs 1.5 apart"},
         [] { return serpentine_spec(SerpentineParams{}, "serpentine-lift"); }},
        {{"straight-pipe", "box 4 x 3 x 2, one straight pipe of diameter 0.1 square to both faces"}, straight_pipe},
        {{"oblique-pipe", "box 4 x 3 x 2, one straight pipe of diameter 0.1 about 10 degrees off square"}, oblique_pipe},
        {{"arc-pipe", "box 4 x 4 x 2, one quarter-circle pipe of diameter 0.1, bend radius 2.5"}, arc_pipe},
        {{"three-pipes", "box 6 x 5 x 3, two straight pipes and one quarter-circle pipe"}, three_pipes},
        {{"bent-pipe", "box 6 x 5 x 3, one polyline pipe with 0.4 bends, not in one plane"}, bent_pipe},
        {{"u-bend", "box 5 x 4 x 3, one U-bend pipe with both ends on the bottom face"}, u_bend},
    };
    return list;
}

}  // namespace

const std::vector<PresetInfo>& preset_list() {
    static const std::vector<PresetInfo> list = [] {
        std::vector<PresetInfo> out;
        for (const Entry& e : entries()) out.push_back(e.info);
        return out;
    }();
    return list;
}

BlockSpec preset_spec(const std::string& name) {
    std::string names;
    for (const Entry& e : entries()) {
        if (e.info.name == name) return e.make();
        names += (names.empty() ? "" : ", ") + e.info.name;
    }
    throw Error("no preset named '" + name + "': choose one of " + names);
}

}  // namespace tubemesh::geom
