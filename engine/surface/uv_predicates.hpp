#pragma once
// Orientation in a face's parameter plane, the one exact test the surface mesher's topology
// rests on (walks, cavity shape, flips, boundary recovery). In-circle tests need not be exact:
// the cavity is checked for star shape with this predicate before it is used.
#include "engine/geometry/surface_map.hpp"  // Uv

namespace tubemesh::surface {

// Sign of det[b - a, c - a]: +1 when a, b, c turn counter-clockwise in the (u, v) plane,
// -1 clockwise, 0 when collinear. Exact: a floating-point filter, and the exact orient3d of
// the predicates module on the points lifted to z = 0 (with the fourth point straight above a)
// when the filter cannot decide.
int orient2d(Uv a, Uv b, Uv c);

}  // namespace tubemesh::surface
