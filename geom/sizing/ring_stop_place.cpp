#include "geom/sizing/ring_stop_place.hpp"

#include <algorithm>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::geom {

namespace {

// The point of `line` at arc length s (cumulative lengths `at`), and the direction there.
void point_at(const std::vector<Vec3>& line, const std::vector<double>& at, double s, Vec3& p, Vec3& t) {
    std::size_t i = 1;
    while (i + 1 < line.size() && at[i] < s) ++i;
    const double w = at[i] > at[i - 1] ? std::clamp((s - at[i - 1]) / (at[i] - at[i - 1]), 0.0, 1.0) : 0.0;
    p = line[i - 1] + w * (line[i] - line[i - 1]);
    t = line[i] - line[i - 1];
    t = (1.0 / norm(t)) * t;
}

}  // namespace

std::optional<RingCut> ring_cut(const TubeInfo& tube, const std::vector<double>& clearance, double need) {
    const std::vector<Vec3>& line = tube.centre_line;
    if (line.size() < 2 || clearance.size() != line.size()) return std::nullopt;
    const double r = tube.radius_min;
    const std::size_t n = line.size();
    std::vector<double> at(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) at[i] = at[i - 1] + norm(line[i] - line[i - 1]);
    std::vector<bool> bad(n);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
        bad[i] = clearance[i] < need;
        any = any || bad[i];
    }
    if (!any) return std::nullopt;
    const double total = at.back();
    const double first = at[static_cast<std::size_t>(std::find(bad.begin(), bad.end(), true) - bad.begin())];
    const double last = at[n - 1 - static_cast<std::size_t>(std::find(bad.rbegin(), bad.rend(), true) - bad.rbegin())];
    const double margin = 2 * r;
    const double from_first = first - margin, from_last = total - last - margin;
    if (std::max(from_first, from_last) < kShortestStoppedRing * 2 * r) return std::nullopt;
    RingCut cut;
    if (from_first >= from_last) {
        point_at(line, at, from_first, cut.centre, cut.tangent);
        cut.keep = line.front();
        cut.kept_length = from_first;
        cut.spot = first;
    } else {
        point_at(line, at, last + margin, cut.centre, cut.tangent);
        cut.keep = line.back();
        cut.kept_length = from_last;
        cut.spot = total - last;
    }
    return cut;
}

}  // namespace tubemesh::geom
