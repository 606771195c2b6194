#pragma once
// Closed-form geometry of the two host shapes (box, cylinder): inside tests, distances and face
// normals, used to place pipes and check their clearances without OpenCASCADE.
#include <optional>

#include "engine/core/vec3_ops.hpp"  // Vec3 arithmetic shared with the engine
#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

double host_volume(const HostSpec& host);
// The diagonal of the host's bounding box: the length scale for tolerances and extensions.
double host_extent(const HostSpec& host);
// Distance from p to the host boundary: positive inside, negative outside.
double signed_boundary_distance(const HostSpec& host, const Vec3& p);
// Outward unit normal of the boundary face that p lies on (within tol), if any. A point on an
// edge gets the normal of the first face found; presets keep pipe ends away from edges.
std::optional<Vec3> boundary_normal(const HostSpec& host, const Vec3& p, double tol);

// Unit vector along a, as (1 / |a|) · a (a must not be zero): the built blocks' coordinates
// depend on this rounding, which differs from vec3_ops' normalized (a / |a|) in the last bit.
Vec3 unit(const Vec3& a);

}  // namespace tubemesh::geom
