#include "geom/sizing/ring_stop_place.hpp"

#include <algorithm>
#include <array>

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

namespace {

// Both ends' cuts, each with its stretch's length; nullopt when no point is a spot.
std::optional<std::array<RingCut, 2>> end_cuts(const TubeInfo& tube, const std::vector<double>& clearance, double need) {
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
    std::array<RingCut, 2> cuts;
    point_at(line, at, first - margin, cuts[0].centre, cuts[0].tangent);
    cuts[0].keep = line.front();
    cuts[0].kept_length = first - margin;
    cuts[0].spot = first;
    point_at(line, at, last + margin, cuts[1].centre, cuts[1].tangent);
    cuts[1].keep = line.back();
    cuts[1].kept_length = total - last - margin;
    cuts[1].spot = total - last;
    return cuts;
}

bool worth_a_ring(const RingCut& cut, const TubeInfo& tube) {
    return cut.kept_length >= kShortestStoppedRing * 2 * tube.radius_min;
}

}  // namespace

std::optional<RingCut> ring_cut(const TubeInfo& tube, const std::vector<double>& clearance, double need) {
    const auto cuts = end_cuts(tube, clearance, need);
    if (!cuts) return std::nullopt;
    const RingCut& longer = (*cuts)[0].kept_length >= (*cuts)[1].kept_length ? (*cuts)[0] : (*cuts)[1];
    if (!worth_a_ring(longer, tube)) return std::nullopt;
    return longer;
}

std::vector<RingCut> ring_cuts(const TubeInfo& tube, const std::vector<double>& clearance, double need) {
    const auto cuts = end_cuts(tube, clearance, need);
    if (!cuts) return {};
    const bool front_longer = (*cuts)[0].kept_length >= (*cuts)[1].kept_length;
    std::vector<RingCut> out;
    for (const RingCut& c : {(*cuts)[front_longer ? 0 : 1], (*cuts)[front_longer ? 1 : 0]})
        if (worth_a_ring(c, tube)) out.push_back(c);
    return out;
}

std::optional<RingCut> cut_before_end(const TubeInfo& tube, int end, const std::vector<Vec3>& junction) {
    std::vector<Vec3> line = tube.centre_line;
    if (line.size() < 2 || junction.empty()) return std::nullopt;
    if (end == 0) std::reverse(line.begin(), line.end());
    std::vector<double> at(line.size(), 0.0);
    for (std::size_t i = 1; i < line.size(); ++i) at[i] = at[i - 1] + norm(line[i] - line[i - 1]);
    // Each point's arc length where it projects on the line's nearest segment.
    double first = at.back();
    for (const Vec3& p : junction) {
        double best = -1, s = 0;
        for (std::size_t i = 1; i < line.size(); ++i) {
            const Vec3 d = line[i] - line[i - 1];
            const double len2 = dot(d, d);
            const double w = len2 > 0 ? std::clamp(dot(p - line[i - 1], d) / len2, 0.0, 1.0) : 0.0;
            const double dist = distance2(line[i - 1] + w * d, p);
            if (best < 0 || dist < best) {
                best = dist;
                s = at[i - 1] + w * (at[i] - at[i - 1]);
            }
        }
        first = std::min(first, s);
    }
    RingCut cut;
    cut.kept_length = first - kJunctionMargin * 2 * tube.radius_min;
    cut.spot = first;
    cut.keep = line.front();
    if (cut.kept_length < kShortestStoppedRing * 2 * tube.radius_min) return std::nullopt;
    point_at(line, at, cut.kept_length, cut.centre, cut.tangent);
    return cut;
}

}  // namespace tubemesh::geom
