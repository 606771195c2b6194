#pragma once
// How thick each tube's hex ring may be, per place along it and direction around it
// (docs/architecture.md, "Sizing is local"): from the clearance in D directions around the centre line
// at its points (TubeInfo::centre_line) to the faces of the model (not tube walls, not the
// tube's own hosts) and to the tubes' walls (other tubes, and the tube's own runs farther
// along it), over the room a ring and its pyramids take there: the sizing guards' 3.2 St
// towards a face, 4.2 St between two tubes (two rings share that gap), with their 95 %
// margin. Each direction's clearance is the nearest hit of a small fan of rays from the wall
// (±25° around and along the direction), which a face met at a slant or a thin neighbour
// cannot slip through. The thickness is then graded (it grows by at most kRoomGrowth per unit
// length along the centre line and around the ring's outer circumference) and capped at St.
//
// Rays go only as far as a full ring needs, so a tube far from everything costs a box test per
// point and gets an empty RingRoom: the sweep then places its nodes as the paper does.
//
// No OpenCASCADE header here.
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "geom/model/model.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// Directions around the axis.
inline constexpr int kRoomDirections = 16;
// Largest growth of the allowed thickness per unit length, along the tube and around it.
inline constexpr double kRoomGrowth = 0.3;

// One RingRoom per tube (same order), for rings of thickness sweep_size.
std::vector<RingRoom> ring_rooms(const Model& model, const std::vector<TubeInfo>& tubes, double sweep_size);

}  // namespace tubemesh::geom
