#pragma once
// Where a pipe that has room for a ring along most of its length but not at one spot (a face or
// another pipe too near there) stops its ring: on a cross-section a diameter before the first
// place, seen from the end with the longer stretch of room, where the clearance leaves less room
// than the caller asks for. The wall beyond gets tets (geom/tubes/ring_stop.hpp).
//
// No OpenCASCADE header here.
#include <optional>

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

}  // namespace tubemesh::geom
