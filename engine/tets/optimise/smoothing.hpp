#pragma once
// Smoothing of the free points of a TetDomain (paper §5). A point whose worst tet is below a
// floor moves towards the centroid of its neighbours, its optimal-Delaunay position (the
// volume-weighted mean of its tets' circumcentres) or the position that makes its worst tet
// regular, when that worst tet gets better. Otherwise (and for every point at or above the
// floor) it moves along the gradient of the sum of its tets' collapses, or towards the ODT
// position or the centroid, when that sum rises and the worst tet stays at or above
// min(its value, floor); never when a tet inverts (exact orient3d).
// Front points [0, front_points) never move, but for the pyramid apexes the domain marks
// movable (TetDomain::apex_rank), which also keep their pyramids at apex_floor or better; the
// topology does not change.
//
// Parallel and deterministic: points are greedily coloured in index order so that no two
// points of a colour share a tet (point_colouring.hpp); the points of one colour move at once
// (tbb::parallel_for), each reading only its own tets, whose other points do not move in that
// colour.
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/core/pulse.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct SmoothingCounts {
    std::uint64_t moves = 0;    // accepted moves
    std::uint64_t colours = 0;  // colours of the point colouring
};

// Which moves a fair star (worst tet at or above 0.5) tries for its sum of collapses: along its
// ascent, then towards its ODT position and its centroid (All), or along its ascent alone
// (AscentForFair: later passes, where the ascent wins nearly every move, for less than half the
// trials and neither target's cost). Stars with a tet below 0.5 always try every target.
enum class SmoothingTargets { All, AscentForFair };

// `sweeps` sweeps over the free points whose worst tet is below `threshold`; a move must raise
// the worst collapse around the point by more than min_gain, or the sum of the collapses around
// it by more than min_gain per tet (`floor` as above). The first sweep tries the points with
// active[p] set (all when active is nullptr), each later one only the points with a moved point in their star
// (the others would meet the same star again). After them (when sweeps > 0) come up to three
// polish sweeps over the points near a moved point whose worst tet was below 0.35, with finer
// steps and more targets: those few stars decide the minimum. A moved point gets
// changed[p] = 1 (one flag per point). The domain has no free slots. `collapses`: the collapse
// of every tet (collapse_of over its vertex row), read instead of computed and kept up to date.
SmoothingCounts smooth_points(TetDomain& dom, int sweeps, double threshold, double min_gain, double floor,
                              const std::vector<std::uint8_t>* active, std::vector<std::uint8_t>& changed,
                              std::vector<double>& collapses, SmoothingTargets targets = SmoothingTargets::All,
                              const Pulse& pulse = {});

}  // namespace tubemesh::tets
