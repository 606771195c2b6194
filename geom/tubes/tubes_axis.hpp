#pragma once
// A tube's centre line (paper §3.2), from generator lines of the wall.
//
// The paper takes the midpoints of two opposite lines' nodes, each line cut by its own arc
// length. That is exact for a straight tube and for a torus cut square, but where the ends are
// oblique on a curved tube, or the curvature varies, the lines run at different speeds and
// equal fractions no longer sit in one cross-section; and "opposite" by the surface's
// parameter is only opposite when the section's parametrisation is proportional to angle,
// which a rational B-spline circle's is not: the midpoints drifted off the axis by 1e-3 to 1e-2
// of the radius. So each station is a cross-section: the plane through line 0's point normal to
// the lines, where four lines (started a quarter of E1's length apart) cross it, and the circle
// through those four points. Exact for any circular section, whatever angles the lines sit at;
// for an oval one it is the best circle through four points around it.
#include <array>
#include <optional>
#include <vector>

#include "geom/tubes/tubes_generator.hpp"
#include "geom/tubes/tubes_wall.hpp"

namespace tubemesh::geom {

// Where generator 0 (and ring node 0) starts along E1, as a fraction of E1's length from its
// first vertex. Off the positions where seams and splits usually sit (the vertex itself,
// halves, thirds, quarters), so the generator lines start inside a face, not on a split edge.
inline constexpr double kGeneratorStartFraction = 0.125;

struct AxisSample {
    gp_Pnt centre;
    gp_Vec tangent;         // unit, E1 towards E2
    gp_Vec reference;       // unit, orthogonal to tangent, towards generator 0 (ring node 0)
    double radius = 0;      // mean distance from the centre to the four generator lines
    double radius_min = 0;  // smallest and largest of those four
    double radius_max = 0;
    // Radius of curvature of the centre line here: the mean of the four lines' own radii of
    // curvature (exact for a planar bend of a circular tube, where opposite lines are offsets
    // at +-r); +inf where the lines are straight.
    double bend_radius = 0;
};

class TubeAxis {
public:
    // Generator 0 starts `start_fraction` of E1's length from E1's first vertex; 1, 2 and 3 a
    // quarter, half and three quarters of E1's length further (two opposite pairs on a loop
    // that is a plane section of the tube). nullopt when a line cannot be followed to E2.
    static std::optional<TubeAxis> build(const TubeWall& wall, double start_fraction);

    const Generator& generator(int k) const { return generators_[k]; }
    // Of the centre line: the mean of the four lines' lengths (exact for a planar bend, whose
    // opposite lines are offsets at +-r, and for a mitre, whose lines gain and lose equally).
    double length() const { return (lengths_[0] + lengths_[1] + lengths_[2] + lengths_[3]) / 4; }

    // segments + 1 samples evenly spaced by the centre line's arc length. The first and last
    // are the centres of the end loops (across the axis, the circle through the four lines' end
    // points seen along it; along it, the points' mean plane), which lie in the loops' planes
    // when the loops are planar and on the axis of a straight tube however its ends are cut.
    std::vector<AxisSample> stations(int segments) const;
    // Samples along the centre line, about one per diameter and denser in bends (no chord
    // more than 1% of the radius off the axis); all but the first and last are true
    // cross-sections.
    const std::vector<AxisSample>& samples() const { return samples_; }
    double max_kink() const;  // radians

private:
    explicit TubeAxis(std::array<Generator, 4> generators);
    TubeAxis independent_copy() const;  // Generator::independent_copy of every line
    AxisSample end_sample(double sigma) const;
    AxisSample section(double sigma0, std::array<double, 3>& sigmas) const;
    void push(const AxisSample& sample, double sigma0, const std::array<double, 3>& sigmas);
    void refine(std::size_t last, const AxisSample& next, double sigma0, const std::array<double, 3>& sigmas,
                int depth);

    std::array<Generator, 4> generators_;
    std::array<double, 4> lengths_{};
    double radius_ = 0;  // at E1: the scale for judging a section
    double sagitta_tolerance_ = 0;
    std::vector<double> sigma0_;                 // line 0's arc length fraction at each sample
    std::vector<std::array<double, 3>> sigmas_;  // lines 1-3's fractions there
    std::vector<AxisSample> samples_;
    std::vector<double> arc_;  // centre line arc length at each sample
};

}  // namespace tubemesh::geom
