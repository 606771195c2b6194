#pragma once
// Where a pipe that has room for a ring along most of its length but not at one spot (a face or
// another pipe too near there) stops its ring: on a cross-section a diameter before the first
// place, seen from an end, where the clearance leaves less room than the caller asks for. Each end
// with a stretch worth a ring keeps one, so a spot in the middle leaves rings on both sides. The
// wall between gets tets (geom/tubes/ring_stop.hpp).
//
// No OpenCASCADE header here.
#include <optional>
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// A stretch under a ring shorter than this many diameters is not worth a ring of its own.
inline constexpr double kShortestStoppedRing = 2.0;

struct RingCut {
    Vec3 centre, tangent;  // the cross-section, on the centre line
    Vec3 keep;             // the end of the centre line whose stretch keeps the ring
    double kept_length = 0;
    double spot = 0;       // arc length from `keep` to the first place without room
};

// `clearance`: from the wall at each centre-line point to what the pipe was dropped for; a spot is
// a point with less than `need` (the caller's: room for a ring as thick as St, at most the radius,
// and its pyramids; a ring much thinner than its layers are long where it stops leaves its end
// quads' pyramids little room, and the run's retry thins St then). nullopt
// when no point is a spot, or neither end keeps kShortestStoppedRing diameters.
std::optional<RingCut> ring_cut(const TubeInfo& tube, const std::vector<double>& clearance, double need);

// Every end's cut: that of the longer stretch first (ring_cut's), then the other end's when its
// stretch too is kShortestStoppedRing diameters or more; empty when ring_cut gives none.
std::vector<RingCut> ring_cuts(const TubeInfo& tube, const std::vector<double>& clearance, double need);

// Diameters between a ring's end and the wall of another pipe it would meet: at one diameter the
// end quads' pyramids of a T-junction's branch found too little room in front of them.
inline constexpr double kJunctionMargin = 2.0;

// Where a tube whose end `end` (0: E1's, 1: E2's) lies on another pipe's wall (a T-junction's
// branch) stops its ring: kJunctionMargin diameters before the first of `junction` (points of that end's loop)
// along its centre line, seen from its other end; nullopt when the stretch left is under
// kShortestStoppedRing diameters.
std::optional<RingCut> cut_before_end(const TubeInfo& tube, int end, const std::vector<Vec3>& junction);

}  // namespace tubemesh::geom
