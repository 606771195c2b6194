#pragma once
// Pipe walls that meet (a T-junction, pipes that cross, an L of two drilled holes), and a blind
// hole: the tube search takes no such group as a tube (it has three or more loops, or one). Each
// cylinder of the group with an open end keeps a ring from that end to a cross-section before the
// other wall (kJunctionMargin diameters, geom/sizing/ring_stop_place.hpp) or before the blind end
// (kBlindMargin); the wall from there on gets tets. Only cylinders are cut: a drilled hole's wall;
// other such walls stay whole, with tets.
//
// No OpenCASCADE header here.
#include <optional>
#include <set>
#include <vector>

#include "geom/model/model.hpp"
#include "geom/sizing/ring_stop_place.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// Diameters between a ring's end and a blind hole's bottom: a flat face in front of the end quads'
// pyramids, with more room than another pipe's wall leaves.
inline constexpr double kBlindMargin = 1.0;

// One cylinder of a group of walls that meet: its faces, its axis, and where along the axis
// (parameters from `origin` along `axis`) its open ends and the other walls it meets lie.
struct JunctionPipe {
    std::vector<int> faces;  // ascending
    Vec3 origin, axis;       // axis: unit
    double radius = 0;
    std::vector<double> open;      // points of its loops on faces that are no pipe wall
    std::vector<double> junction;  // points of its edges shared with another pipe's wall or its bottom
};

// The cylinders of `group` (faces of one rejected group, ascending), each with its open ends and
// junctions; `walls`: every pipe wall face of the model (tubes, groups, walls beyond a stopped
// ring). Faces of the group that are no cylinder are left out.
std::vector<JunctionPipe> junction_pipes(const Model& model, const std::vector<int>& group, const std::set<int>& walls);

// The cuts of a pipe with junctions: one `margin` diameters before its junctions on each side with
// an open end, when the stretch from that end keeps kShortestStoppedRing diameters.
std::vector<RingCut> junction_cuts(const JunctionPipe& pipe, double margin);

// The faces of `group` a stretch of wall cut off by the closed edge `cut` holds on the side of
// `keep`, from a hole loop of another face at its open end to `cut`, as a tube whose second loop is
// `cut` (its host the face beyond); nullopt when that side is no tube.
std::optional<TubeInfo> stretch_tube(const Model& model, const std::vector<int>& group, int cut, const Vec3& keep);

}  // namespace tubemesh::geom
