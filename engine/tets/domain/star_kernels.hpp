#pragma once
// What a point's star (the tets with that point as a vertex) tells about moving the point: its
// corners gathered once, the quality of the star with the point elsewhere, the targets a move
// may head for (centroid, optimal-Delaunay position, a tet's regular apex, the gradient of the
// sum of collapses), and whether a position inverts a tet. Read by the relaxation, the smoothing
// and the rescue of the worst tets.
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

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
