#pragma once
// The standard element measures engineers compare meshers in, with Verdict's definitions (the
// library behind ParaView's MeshQuality filter), beside the paper's measures in quality.hpp.
// Each is 1 (or 70.53 degrees) for the regular element. Flat or inverted elements keep a
// meaningful value: a scaled Jacobian goes to 0 and below, an aspect ratio to +infinity.
#include <array>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

// sqrt(2) · det[p1 - p0, p2 - p0, p3 - p0] over the largest product of the three edge lengths
// at a corner (Verdict's tet scaled Jacobian).
double tet_scaled_jacobian(const std::array<Vec3, 4>& p);

// The smallest of the six dihedral angles, in degrees. (Verdict's tet "minimum angle", which
// ParaView shows, takes the supplement at two of the six edges: its face normals are not
// oriented alike; it is this value when those two angles are not obtuse.)
double tet_min_dihedral_degrees(const std::array<Vec3, 4>& p);

// h_max · (sum of the face areas) / (2 sqrt(6) · 3 V): the longest edge over the inradius,
// normalised to 1 for the regular tet (Verdict's tet aspect ratio). +infinity when V <= 0.
double tet_aspect_ratio(const std::array<Vec3, 4>& p);

// Verdict's hex scaled Jacobian: the smaller of J_m (hex_quality's corner minimum) and the
// value at the centre, from the three principal axes (differences of opposite face centres).
double hex_verdict_scaled_jacobian(const std::array<Vec3, 8>& p);
double hex_centre_scaled_jacobian(const std::array<Vec3, 8>& p);  // the centre's value alone

}  // namespace tubemesh
