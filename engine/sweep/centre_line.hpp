#pragma once
// A tube's centre line resampled into equal steps, with a frame at every station.
#include <functional>
#include <span>
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "engine/core/vec3.hpp"

namespace tubemesh::sweep {

struct Station {
    Vec3 centre;
    Vec3 tangent;    // unit
    Vec3 reference;  // unit, orthogonal to tangent: angle 0 of the cross-section
    double radius = 0;
    double s = 0;  // distance along the centre line from the first station
};

struct CentreLine {
    std::vector<Station> stations;
    double length = 0;
    bool frame_fallback = false;  // the input's references were unusable: rotation-minimising frames
};

// Resamples `input` (geom's stations, at least two) into the whole number of equal steps
// nearest to length / step (at least one). Distance along the line is the input polyline's
// chord length: geom samples it by arc length finely enough that the difference is second
// order. Between two input stations the centre follows the cubic Hermite curve through them
// with their tangents (so a bend stays round, not a polygon); tangents are that curve's,
// references and radii are interpolated linearly, references then made orthogonal to the
// tangent. The first and last stations are the input's.
//
// When an input reference is zero, not finite or within 30 degrees of its tangent, all are
// replaced by rotation-minimising frames started at `first_node` (ring1[0]).
// With `local_step` (the step wanted at arc length s, at most `step`), the stations are spaced
// by it instead (graded_positions in the .cpp): a ring thinned somewhere gets shorter steps
// there only.
// Throws tubemesh::Error for zero tangents or repeated stations.
CentreLine resample_centre_line(std::span<const TubeStation> input, double step, const Vec3& first_node,
                                const std::function<double(double)>& local_step = {});

}  // namespace tubemesh::sweep
