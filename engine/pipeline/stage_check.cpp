#include "engine/pipeline/stage_check.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "engine/core/timing.hpp"

namespace tubemesh {

bool violation_expected(ViolationKind kind, Stage reached) {
    // Only these two stages store faces that no cell owns yet; any later stage (the tets)
    // owns them all and gets the full check.
    const bool partial = reached == Stage::Surface || reached == Stage::Pyramids;
    return partial && (kind == ViolationKind::BoundaryFaceNotOnCell || kind == ViolationKind::OpenBoundary);
}

std::size_t front_defects(const std::vector<index_t>& triangles) {
    // One record per triangle edge: the sorted pair and +1 / -1 for its direction. A good
    // edge is a run of exactly two records whose directions cancel.
    struct Edge {
        index_t lo, hi;
        int direction;
    };
    std::vector<Edge> edges;
    edges.reserve(triangles.size());
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const index_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
            edges.push_back(a < b ? Edge{a, b, 1} : Edge{b, a, -1});
        }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& e, const Edge& f) { return std::pair(e.lo, e.hi) < std::pair(f.lo, f.hi); });
    std::size_t defects = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        int sum = 0;
        while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) sum += edges[j++].direction;
        if (j - i != 2 || sum != 0) ++defects;
        i = j;
    }
    return defects;
}

void check_result(PipelineResult& result, const ProgressCallback& progress) {
    const auto t0 = Clock::now();
    PhaseProgress phase(progress, "check", 1);
    result.check = check_mesh(result.mesh, [&phase] { phase.pulse(); });
    std::string failures;
    for (const Violation& v : result.check.violations) {
        if (violation_expected(v.kind, result.reached)) continue;
        CheckReport one;
        one.violations.push_back(v);
        failures += (failures.empty() ? "" : "; ") + describe(one);
    }
    const std::size_t front = result.reached == Stage::Pyramids ? front_defects(result.tet_front) : 0;
    if (front > 0)
        failures += (failures.empty() ? "" : "; ") + std::string("OpenFront: ") + std::to_string(front) +
                    " edges of the tet region's boundary are not shared by exactly two triangles";
    if (!failures.empty())
        throw Error(std::string("the mesh failed the validity and conformity check after the ") +
                    stage_name(result.reached) + " stage, so no file was written: " + failures);
    PhaseReport r{"check", seconds_since(t0), {}, {}};
    r.counts = {{"interior faces", double(result.check.interior_faces)},
                {"free faces", double(result.check.boundary_faces)}};
    r.statistics = {{"volume", result.check.volume}, {"boundary area", result.check.boundary_area}};
    phase.finish();
    result.seconds += r.seconds;
    result.phases.push_back(std::move(r));
}

}  // namespace tubemesh
