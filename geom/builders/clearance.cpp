#include "geom/builders/clearance.hpp"

#include <algorithm>
#include <cmath>

#include "geom/builders/host_geometry.hpp"

namespace tubemesh::geom {

namespace {

double arc_spacing(const PipeSamples& p) {
    double len = 0;
    for (std::size_t i = 1; i < p.points.size(); ++i) len += norm(p.points[i] - p.points[i - 1]);
    return p.points.size() > 1 ? len / static_cast<double>(p.points.size() - 1) : 0.0;
}

}  // namespace

double pipe_gap(const PipeSamples& a, const PipeSamples& b) {
    double best = Clearance::kNone;
    for (const Vec3& p : a.points)
        for (const Vec3& q : b.points) best = std::min(best, norm(p - q));
    return best - a.radius - b.radius;
}

Clearance measure_clearance(const std::vector<PipeSamples>& pipes, const HostSpec& host, double end_zone) {
    Clearance c;
    for (std::size_t a = 0; a < pipes.size(); ++a) {
        const PipeSamples& pa = pipes[a];
        for (std::size_t b = a + 1; b < pipes.size(); ++b) {
            const double gap = pipe_gap(pa, pipes[b]);
            if (gap < c.pipe_gap) c.pipe_gap = gap, c.pipe_a = static_cast<int>(a), c.pipe_b = static_cast<int>(b);
        }

        // Parts of one pipe count as "far apart" beyond three times `reach` (a diameter of pipe
        // plus a diameter of gap) along it: along a bend of radius at least `reach`, points that
        // close in arc length cannot come closer than `reach` in space.
        const double h = arc_spacing(pa);
        const double reach = 4 * pa.radius;
        const std::size_t skip = h > 0 ? static_cast<std::size_t>(std::ceil(3 * reach / h)) : pa.points.size();
        for (std::size_t i = 0; i < pa.points.size(); ++i)
            for (std::size_t j = i + skip; j < pa.points.size(); ++j) {
                const double gap = norm(pa.points[i] - pa.points[j]) - 2 * pa.radius;
                if (gap < c.self_gap) c.self_gap = gap, c.self_pipe = static_cast<int>(a);
            }

        const std::size_t zone = h > 0 ? static_cast<std::size_t>(std::ceil(end_zone / h)) : 0;
        for (std::size_t i = zone; i + zone < pa.points.size(); ++i) {
            const double gap = signed_boundary_distance(host, pa.points[i]) - pa.radius;
            if (gap < c.boundary_gap) c.boundary_gap = gap, c.boundary_pipe = static_cast<int>(a);
        }
    }
    return c;
}

}  // namespace tubemesh::geom
