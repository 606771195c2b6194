#pragma once
// Closed-form geometry of the two host shapes (box, cylinder): inside tests, distances and face
// normals, used to place pipes and check their clearances without OpenCASCADE.
#include <optional>

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

// Small vector helpers shared by the builders.
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const Vec3& a, const Vec3& b);
Vec3 cross(const Vec3& a, const Vec3& b);
double norm(const Vec3& a);
Vec3 normalized(const Vec3& a);

}  // namespace tubemesh::geom
