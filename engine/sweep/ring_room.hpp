#pragma once
// Reading a tube's RingRoom (tube_data.hpp): how thick its ring may be at a place and in a
// direction, as a share of the ring's St.
#include <span>

#include "engine/geometry/tube_data.hpp"

namespace tubemesh::sweep {

// The thickness allowed at arc length s in direction dir (any vector not along the axis; its
// angle is taken in the room's frame at the samples around s). +infinity for an empty room.
double room_thickness(const RingRoom& room, double s, const Vec3& dir);

// min(1, room_thickness / sweep_size): what the ring's radial offsets are multiplied by there.
double room_scale(const RingRoom& room, double sweep_size, double s, const Vec3& dir);

// Smallest thickness the room allows around the ring at arc length s (linear between samples);
// +infinity for an empty room.
double thinnest_at(const RingRoom& room, double s);

// Smallest thickness the room allows anywhere; +infinity for an empty room.
double thinnest(const RingRoom& room);

}  // namespace tubemesh::sweep
