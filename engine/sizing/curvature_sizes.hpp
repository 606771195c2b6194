#pragma once
// Sizes from the faces' own curvature: where a face bends with radius R it asks for triangles
// of at most kCurvatureSize R, so that a hole that is not a tube (a blind hole, a through hole
// the tube rules reject) is meshed around its circumference even when S is larger than the
// hole. Without this the tet front of a 0.2 blind hole meshed at S = 0.3 crossed itself and
// boundary recovery failed.
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/sizing/field/size_field.hpp"

namespace tubemesh {

// A triangle edge then turns by at most about half a radian along the face.
inline constexpr double kCurvatureSize = 0.5;

// Appends a source at each point of a 9 x 9 grid over the face's parameter box where the
// face's curvature asks for less than `max_size` (the normal's turn over a grid step, a
// finite-difference estimate). A face with one normal on a 3 x 3 grid (a plane) adds nothing.
void add_curvature_sources(const SurfaceMap& map, double max_size, std::vector<SizeSource>& out);

}  // namespace tubemesh
