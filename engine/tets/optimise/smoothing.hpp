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

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct SmoothingCounts {
    std::uint64_t moves = 0;    // accepted moves
    std::uint64_t colours = 0;  // colours of the point colouring
};

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
                              std::vector<double>& collapses);

// True when no tet of `star` (tets with point p as a vertex) inverts with p at x (exact orient3d).
bool none_inverted(const TetDomain& dom, index_t p, std::span<const index_t> star, const Vec3& x);

// Where p would make tet t (p one of its vertices) regular over its opposite face: above the
// face's centroid, at the regular tet's height for the face's mean edge length, on p's side.
Vec3 regular_apex(const TetDomain& dom, index_t t, index_t p);

// The corners of a star's tets (tets with point p as a vertex) in vertex-row order, gathered once
// per point: every target and every trial position reads them again. `at`: where p is among them.
// `opposite`: each tet's face opposite p, (a, b, c) ordered so that (a, b, c, p) is positive, its
// normal n = (b - a) x (c - a) and 4 area² = |n|²: a trial position x changes only the other
// three faces and the volume (n · (x - a) / 2 = 3V), so star_quality computes those alone.
// `paired`: the same faces of tets 1, 2, ... two at a time, each of the 13 numbers (a, b, c, n,
// area4) as a pair (tet 2j+1, tet 2j+2), for star_quality's two-lane evaluation.
struct StarCorners {
    struct Opposite {
        Vec3 a, b, c, n;
        double area4;
    };
    static constexpr std::size_t kPairStride = 26;
    std::vector<std::array<Vec3, 4>> corners;
    std::vector<std::uint8_t> at;
    std::vector<Opposite> opposite;
    std::vector<double> paired;
};
// with_faces = false: the corners and `at` alone (what odt_target and star_centroid read).
void gather_star_corners(const TetDomain& dom, index_t p, std::span<const index_t> star, StarCorners& out,
                         bool with_faces = true);
// The mean of the star's corners other than p (each counted once per tet it is in).
Vec3 star_centroid(const StarCorners& star);

// The optimal-Delaunay (ODT) position of the star's point (Chen and Holst): the mean of its tets'
// circumcentres weighted by their volumes, times weight[k] for tet k when `weight` is given (a
// density: the relaxation passes 1 / h^3). ODT spreads points evenly where the centroid only
// averages them. Tets that are not positive are left out; `fallback` when none is.
Vec3 odt_target(const StarCorners& star, const Vec3& fallback, std::span<const double> weight = {});

// The direction in which the sum of the star's collapses rises fastest when p moves (zero when
// there is none); `collapse[k]`: the collapse of tet k as it is (tets not above 0 left out).
Vec3 ascent_direction(const StarCorners& star, std::span<const double> collapse);

// The smallest collapse and the sum of collapses of the star's tets with p placed at x.
struct StarQuality {
    double worst = std::numeric_limits<double>::infinity();
    double sum = 0;
};
// Stops (returning what it has) at the first tet at or below `give_up`: a caller that rejects
// such a position anyway saves the rest (-infinity: never stops).
StarQuality star_quality(const StarCorners& star, const Vec3& x,
                         double give_up = -std::numeric_limits<double>::infinity());

}  // namespace tubemesh::tets
