#include "geom/tubes/tubes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geom/tubes/tubes_axis.hpp"
#include "geom/tubes/tubes_topology.hpp"
#include "geom/tubes/tubes_wall.hpp"

namespace tubemesh::geom {
namespace {

TubeInfo describe(const TubeCandidate& c, const TubeAxis& axis) {
    TubeInfo info;
    info.faces = c.faces;
    for (int k = 0; k < 2; ++k) {
        info.hosts[k] = c.loops[k].host;
        info.loop_lengths[k] = c.loops[k].length;
        for (const LoopEdge& e : c.loops[k].edges) info.loops[k].push_back(e.edge);
    }
    info.length = axis.length();
    info.radius_min = std::numeric_limits<double>::infinity();
    info.min_curvature_radius = std::numeric_limits<double>::infinity();
    const std::vector<AxisSample>& samples = axis.samples();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const gp_Pnt& c = samples[i].centre;
        info.centre_line.push_back({c.X(), c.Y(), c.Z()});
        info.min_curvature_radius = std::min(info.min_curvature_radius, samples[i].bend_radius);
        // The end samples are not cross-sections: an oblique loop is no measure of the radius.
        if (i == 0 || i + 1 == samples.size()) continue;
        info.radius_min = std::min(info.radius_min, samples[i].radius_min);
        info.radius_max = std::max(info.radius_max, samples[i].radius_max);
    }
    info.max_kink_deg = axis.max_kink() * 180 / std::numbers::pi;
    return info;
}

}  // namespace

std::optional<TubeInfo> candidate_tube(const TopologyIndex& index, const TubeCandidate& candidate, std::string& why) {
    const auto wall = TubeWall::build(index, candidate, TubeOptions{}, why);
    if (!wall) return std::nullopt;
    const auto axis = TubeAxis::build(*wall, kGeneratorStartFraction);
    if (!axis) {
        why = "no generator line of the wall leads from one loop to the other";
        return std::nullopt;
    }
    return describe(candidate, *axis);
}

TubeSearch find_tubes(const Model& model, const TubeOptions& options) {
    const TopologyIndex index(model);
    CandidateSearch found = find_tube_candidates(index, options);
    TubeSearch out;
    out.rejected = std::move(found.rejected);
    for (const TubeCandidate& c : found.candidates) {
        std::string why;
        const auto wall = TubeWall::build(index, c, options, why);
        if (!wall) {
            out.rejected.push_back({c.faces, why, 2, why.starts_with(TubeWall::kCreaseReason)});
            continue;
        }
        const auto axis = TubeAxis::build(*wall, kGeneratorStartFraction);
        if (!axis) {
            out.rejected.push_back({c.faces, "no generator line of the wall leads from one loop to the other"});
            continue;
        }
        out.tubes.push_back(describe(c, *axis));
    }
    std::sort(out.tubes.begin(), out.tubes.end(),
              [](const TubeInfo& a, const TubeInfo& b) { return a.faces.front() < b.faces.front(); });
    return out;
}

}  // namespace tubemesh::geom
