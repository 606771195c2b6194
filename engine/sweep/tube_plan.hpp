#pragma once
// Everything about one tube's ring that is decided before its nodes are placed: dimensions,
// stations, end sections, and how angles and end depths fade along the tube.
#include <array>
#include <memory>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/sweep/centre_line.hpp"
#include "engine/sweep/ring_ends.hpp"
#include "engine/sweep/sweep.hpp"
#include "engine/sweep/wall_projection.hpp"

namespace tubemesh::sweep {

struct TubePlan {
    index_t tube = 0;
    int n = 0;       // nodes around
    int layers = 0;  // L
    int turn = 1;    // +1: ring nodes turn right-handed about the tangent
    double sweep_size = 0;
    double radius = 0;  // mean of the stations' radii
    double step = 0;    // wanted axial step (the stations' is line.length / (stations - 1))
    std::vector<double> offsets;  // radial_offsets: distance of node j from the wall
    CentreLine line;
    std::array<EndSection, 2> ends;  // at the first and the last station
    std::array<const SurfaceMap*, 2> hosts{};
    // The cross-sections a stopped end lies on (TubeData::stops); hosts[e] points at it then.
    std::array<std::shared_ptr<const SurfaceMap>, 2> stop_planes;
    WallProjection wall;  // onto the tube's wall faces
    // Where the ring is thinner than St (TubeData::room); `thin` says whether it is anywhere:
    // without, every node keeps the full offsets and the computation is the paper's.
    const RingRoom* room = nullptr;
    bool thin = false;
    // Per end, per ring node k: the share of the offsets its column has there (1: full).
    std::array<std::vector<double>, 2> end_scale;

    // Angle of node k about the tangent from the reference: base[k] + twist·s/length + the
    // ends' offsets from even spacing, each faded by its end's weight.
    std::vector<double> base;
    double twist = 0;
    std::array<std::vector<double>, 2> angle_offset;
    std::array<double, 2> blend{};  // lengths over which the ends' weights fall from 1 to 0

    // 1 at end e's station, falling linearly to 0 at `blend[e]` from it.
    double weight(int e, double s) const;
    double angle(int k, double s) const;
    // The share of St the ring may take at arc length s in direction dir: 1 unless `thin`.
    double scale(double s, const Vec3& dir) const;
    int stations() const { return static_cast<int>(line.stations.size()); }
};

// Validates one tube and plans its ring. Throws tubemesh::Error (without the tube's name: the
// caller adds it) for input that cannot be swept.
TubePlan plan_tube(const TubeData& tube, index_t index, const SurfaceLookup& surfaces, const SweepOptions& options);

}  // namespace tubemesh::sweep
