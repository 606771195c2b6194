#include "geom/tubes/tubes_axis.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tubemesh::geom {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Sections sampled along the centre line: about one per tube diameter, within these bounds,
// then more in bends until no chord strays more than kSagittaFraction of the radius from the
// arc (at most kMaxRefinement halvings of a step).
constexpr int kMinSamples = 32;
constexpr int kMaxSamples = 512;
constexpr double kSagittaFraction = 0.01;
constexpr int kMaxRefinement = 10;
// Farther than this many radii from line 0's point, a line's point is on another run of it.
constexpr double kMaxSectionSpread = 4;
// Stations per parallel task: a station costs some tens of microseconds.
constexpr int kStationsPerTask = 32;

using Points = std::array<GeneratorPoint, 4>;

// Radius of curvature of a line at a point, from its derivatives with respect to sigma.
double bend_radius(const GeneratorPoint& g) {
    const double k = g.d2.Magnitude() / g.d1.SquareMagnitude();  // d2 is already the normal part
    return k > 0 ? 1 / k : kInf;
}

// The fraction where line g crosses the plane through p normal to n: Newton from `sigma`,
// clamped to the line (an oblique end can put the crossing beyond it).
double crossing(const Generator& g, const gp_Pnt& p, const gp_Vec& n, double sigma) {
    for (int it = 0; it < 12; ++it) {
        const GeneratorPoint q = g.at(sigma);
        const double f = gp_Vec(p, q.p).Dot(n);
        const double df = q.d1.Dot(n);
        if (!(std::abs(df) > 1e-300)) break;
        const double next = std::clamp(sigma - f / df, 0.0, 1.0);
        if (std::abs(next - sigma) < 1e-15) return next;
        sigma = next;
    }
    return sigma;
}

// The fraction of line g nearest to p, by a scan at steps of half `radius` (then Newton on the
// section plane refines it). Only for a section that strayed: a scan of the whole line.
double nearest_fraction(const Generator& g, const gp_Pnt& p, double radius) {
    const int steps = static_cast<int>(std::clamp(std::ceil(2 * g.length() / std::max(radius, 1e-300)), 16.0, 1e6));
    double best = 0, best_d = kInf;
    for (int i = 0; i <= steps; ++i) {
        const double sigma = static_cast<double>(i) / steps;
        const double d = g.at(sigma).p.SquareDistance(p);
        if (d < best_d) best_d = d, best = sigma;
    }
    return best;
}

// Centre of the circle through the points, fitted in the plane normal to `normal` (algebraic
// least squares, exact when the points lie on a circle). The points' mean when they are
// (nearly) collinear.
gp_Pnt circle_centre(const Points& g, const gp_Vec& normal) {
    gp_XYZ mean(0, 0, 0);
    for (const GeneratorPoint& q : g) mean += q.p.XYZ() / 4;
    const gp_Dir n(normal);
    const gp_Dir a = std::abs(n.X()) < 0.9 ? n.Crossed(gp_Dir(1, 0, 0)) : n.Crossed(gp_Dir(0, 1, 0));
    const gp_Dir b = n.Crossed(a);
    // Minimise sum (x^2 + y^2 + D x + E y + F)^2 over D, E, F: a 3x3 system, by Cramer's rule.
    double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, sxz = 0, syz = 0, sz = 0;
    for (const GeneratorPoint& q : g) {
        const gp_XYZ d = q.p.XYZ() - mean;
        const double x = d.Dot(a.XYZ()), y = d.Dot(b.XYZ()), z = x * x + y * y;
        sxx += x * x, sxy += x * y, syy += y * y, sx += x, sy += y, sxz += x * z, syz += y * z, sz += z;
    }
    const double m[3][3] = {{sxx, sxy, sx}, {sxy, syy, sy}, {sx, sy, 4}};
    const double r[3] = {-sxz, -syz, -sz};
    const auto det3 = [](const double(&k)[3][3]) {
        return k[0][0] * (k[1][1] * k[2][2] - k[1][2] * k[2][1]) - k[0][1] * (k[1][0] * k[2][2] - k[1][2] * k[2][0]) +
               k[0][2] * (k[1][0] * k[2][1] - k[1][1] * k[2][0]);
    };
    const double det = det3(m);
    if (!(std::abs(det) > 1e-12 * std::pow(sxx + syy, 3))) return gp_Pnt(mean);
    double solution[2];
    for (int c = 0; c < 2; ++c) {
        double k[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) k[i][j] = j == c ? r[i] : m[i][j];
        solution[c] = det3(k) / det;
    }
    return gp_Pnt(mean + a.XYZ() * (-solution[0] / 2) + b.XYZ() * (-solution[1] / 2));
}

// A station from four points around the tube, its centre and the axis direction.
AxisSample describe(const Points& g, const gp_Pnt& centre, const gp_Vec& tangent) {
    AxisSample s;
    s.centre = centre;
    s.tangent = tangent;
    s.radius_min = kInf;
    s.bend_radius = 0;
    for (int k = 0; k < 4; ++k) {
        gp_Vec r(s.centre, g[k].p);
        r -= s.tangent * r.Dot(s.tangent);  // an oblique end loop is longer than the section
        const double d = r.Magnitude();
        s.radius += d / 4;
        s.radius_min = std::min(s.radius_min, d);
        s.radius_max = std::max(s.radius_max, d);
        if (k == 0) s.reference = d > 0 ? r / d : gp_Vec(0, 0, 0);
        s.bend_radius += bend_radius(g[k]) / 4;
    }
    return s;
}

gp_Vec mean_tangent(const Points& g) {
    gp_Vec t(0, 0, 0);
    for (const GeneratorPoint& q : g) t += q.d1.Normalized();
    return t.Normalized();
}

}  // namespace

std::optional<TubeAxis> TubeAxis::build(const TubeWall& wall, double start_fraction) {
    const LoopCurve& e1 = wall.loop(0);
    std::array<std::optional<Generator>, 4> found;
    for (int k = 0; k < 4; ++k) {
        found[k] = wall.walk(e1.at((start_fraction + k / 4.0) * e1.length()));
        if (!found[k]) return std::nullopt;
    }
    return TubeAxis({std::move(*found[0]), std::move(*found[1]), std::move(*found[2]), std::move(*found[3])});
}

TubeAxis::TubeAxis(std::array<Generator, 4> generators) : generators_(std::move(generators)) {
    for (int k = 0; k < 4; ++k) lengths_[k] = generators_[k].length();
    const AxisSample first = end_sample(0);
    const double span = length();
    const int n = static_cast<int>(
        std::clamp(std::ceil(span / std::max(2 * first.radius, 1e-300)), double(kMinSamples), double(kMaxSamples)));
    radius_ = first.radius;
    sagitta_tolerance_ = kSagittaFraction * first.radius;

    std::array<double, 3> sigmas{0, 0, 0};
    for (int i = 0; i <= n; ++i) {
        const double sigma0 = static_cast<double>(i) / n;
        AxisSample sample;
        if (i == 0 || i == n) {
            sigmas = {sigma0, sigma0, sigma0};
            sample = end_sample(sigma0);
        } else {
            sample = section(sigma0, sigmas);
        }
        if (i > 0) refine(samples_.size() - 1, sample, sigma0, sigmas, 0);
        push(sample, sigma0, sigmas);
    }
}

void TubeAxis::push(const AxisSample& sample, double sigma0, const std::array<double, 3>& sigmas) {
    samples_.push_back(sample);
    sigma0_.push_back(sigma0);
    sigmas_.push_back(sigmas);
    // Arc length of the centre line as the mean of the four lines' arc lengths at this section:
    // opposite lines of a planar bend are offsets at +-r, so their mean is the axis exactly.
    arc_.push_back(
        (sigma0 * lengths_[0] + sigmas[0] * lengths_[1] + sigmas[1] * lengths_[2] + sigmas[2] * lengths_[3]) / 4);
}

// Inserts sections between the last stored sample and `next` until the chords between them
// stay within the sagitta tolerance of the bend: the centre line a sizing or a sweep reads
// from these samples then follows tight bends.
void TubeAxis::refine(std::size_t last, const AxisSample& next, double sigma0, const std::array<double, 3>& sigmas,
                      int depth) {
    const AxisSample& a = samples_[last];
    const double chord = a.centre.Distance(next.centre);
    double k = std::max(1 / a.bend_radius, 1 / next.bend_radius);
    // Both ends straight but pointing apart: a whole bend lies between them (a tight U-bend on a
    // long pipe, shorter than one first step). Its curvature is at least the turn over the chord.
    if (k == 0 && chord > 0) k = a.tangent.Angle(next.tangent) / chord;
    if (depth >= kMaxRefinement || chord * chord * k / 8 <= sagitta_tolerance_) return;
    const double mid0 = (sigma0_[last] + sigma0) / 2;
    std::array<double, 3> mid_sigmas;
    for (int j = 0; j < 3; ++j) mid_sigmas[j] = (sigmas_[last][j] + sigmas[j]) / 2;
    const AxisSample mid = section(mid0, mid_sigmas);
    refine(last, mid, mid0, mid_sigmas, depth + 1);
    push(mid, mid0, mid_sigmas);
    refine(samples_.size() - 1, next, sigma0, sigmas, depth + 1);
}

AxisSample TubeAxis::end_sample(double sigma) const {
    Points g{generators_[0].at(sigma), generators_[1].at(sigma), generators_[2].at(sigma),
             generators_[3].at(sigma)};
    // The loop's own points (where the rings' nodes 0 sit), not the wall surface's, which are
    // up to the edge tolerance away: the reference then points at ring node 0 exactly.
    for (int k = 0; k < 4; ++k) g[k].p = sigma < 0.5 ? generators_[k].start().p : generators_[k].end().p;
    // The four end points lie on the loop, not in a cross-section (an oblique loop is an
    // ellipse). The paper's midpoints of opposite points put a straight tube's centre on its axis
    // when the loop is planar, but not when it is a saddle (a pipe meeting a curved face
    // obliquely: quarter arc lengths are not quarter turns). So: across the axis, the centre of
    // the circle through the points seen along it (exact for any straight circular tube); along
    // it, the plane through the points' mean with the normal of the quadrilateral's diagonals,
    // which is the loop's own plane when the loop is planar.
    gp_XYZ mean(0, 0, 0);
    for (const GeneratorPoint& q : g) mean += q.p.XYZ() / 4;
    const gp_Vec tangent = mean_tangent(g);
    gp_Pnt centre = circle_centre(g, tangent);
    const gp_Vec normal = gp_Vec(g[0].p, g[2].p).Crossed(gp_Vec(g[1].p, g[3].p));
    const double across = normal.Dot(tangent);
    if (std::abs(across) > 1e-3 * normal.Magnitude())
        centre.Translate(tangent * (gp_Vec(centre, gp_Pnt(mean)).Dot(normal) / across));
    return describe(g, centre, tangent);
}

// The cross-section through line 0's point at sigma0. `sigmas` carries lines 1-3's fractions
// from the previous section, a good start for Newton, and returns this section's.
AxisSample TubeAxis::section(double sigma0, std::array<double, 3>& sigmas) const {
    Points g;
    g[0] = generators_[0].at(sigma0);
    gp_Vec tangent = g[0].d1.Normalized();
    // The plane's normal is the mean tangent of the four lines, which depends on where they
    // cross it: two rounds settle it. A section's four points lie within a diameter or so of
    // each other; Newton from the last section's fractions can land on another run of the same
    // line when a whole bend lies between the two (a serpentine's U-bend on a long pipe): such
    // a line starts again from its point nearest to line 0's.
    for (int round = 0; round < 2; ++round) {
        for (int k = 1; k < 4; ++k) {
            sigmas[k - 1] = crossing(generators_[k], g[0].p, tangent, sigmas[k - 1]);
            g[k] = generators_[k].at(sigmas[k - 1]);
            if (g[k].p.Distance(g[0].p) > kMaxSectionSpread * radius_) {
                sigmas[k - 1] =
                    crossing(generators_[k], g[0].p, tangent, nearest_fraction(generators_[k], g[0].p, radius_));
                g[k] = generators_[k].at(sigmas[k - 1]);
            }
        }
        tangent = mean_tangent(g);
    }
    return describe(g, circle_centre(g, tangent), tangent);
}

std::vector<AxisSample> TubeAxis::stations(int segments) const {
    std::vector<AxisSample> out(static_cast<std::size_t>(std::max(segments, 1)) + 1);
    out.front() = samples_.front();
    out.back() = samples_.back();
    const double total = length();
    // Each station is a section started from the stored sample before it, not from the station
    // before it, so they are independent: evaluated in parallel, each thread on its own copy of
    // the lines.
    tbb::enumerable_thread_specific<std::optional<TubeAxis>> copies;
    tbb::parallel_for(tbb::blocked_range<int>(1, static_cast<int>(out.size()) - 1, kStationsPerTask),
                      [&](const tbb::blocked_range<int>& r) {
                          std::optional<TubeAxis>& copy = copies.local();
                          if (!copy) copy.emplace(independent_copy());
                          for (int k = r.begin(); k != r.end(); ++k) {
                              const double s = total * k / segments;
                              const auto it = std::upper_bound(arc_.begin(), arc_.end(), s);
                              const std::size_t i = std::clamp<std::size_t>(it - arc_.begin(), 1, arc_.size() - 1);
                              const double w = (s - arc_[i - 1]) / std::max(arc_[i] - arc_[i - 1], 1e-300);
                              // Linear in sigma between samples: the station lands within O(h^2 k) of
                              // arc length s.
                              const double sigma0 = sigma0_[i - 1] + w * (sigma0_[i] - sigma0_[i - 1]);
                              std::array<double, 3> sigmas = sigmas_[i - 1];
                              out[static_cast<std::size_t>(k)] = copy->section(sigma0, sigmas);
                          }
                      });
    return out;
}

TubeAxis TubeAxis::independent_copy() const {
    TubeAxis copy = *this;
    for (int k = 0; k < 4; ++k) copy.generators_[k] = generators_[k].independent_copy();
    return copy;
}

double TubeAxis::max_kink() const {
    double worst = 0;
    for (const Generator& g : generators_) worst = std::max(worst, g.max_kink());
    return worst;
}

}  // namespace tubemesh::geom
