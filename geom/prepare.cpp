#include "geom/prepare.hpp"

#include <fmt/format.h>

#include <cmath>
#include <unordered_set>

#include "geom/discretize.hpp"
#include "geom/surface_map_occt.hpp"

namespace tubemesh::geom {

namespace {

std::string join(const std::vector<int>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (i) s += ',';
        s += std::to_string(ids[i]);
    }
    return s;
}

}  // namespace

PreparedModel prepare_model(const Model& model, const PrepareOptions& options) {
    PreparedModel p;
    p.tubes = find_tubes(model, options.tubes);
    p.plan = plan_sizes(model, p.tubes.tubes, options.sizing);
    p.geometry = discretize(model, p.tubes.tubes, p.plan);
    p.maps = make_surface_maps(model);
    return p;
}

PipelineInput PreparedModel::pipeline_input() const {
    std::unordered_set<index_t> walls;
    for (const TubeData& t : geometry.tubes) walls.insert(t.wall_faces.begin(), t.wall_faces.end());
    std::vector<PipelineFace> faces;
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const index_t id = static_cast<index_t>(i + 1);
        faces.push_back({id, walls.count(id) > 0});
    }
    const auto* m = &maps;
    SurfaceLookup lookup = [m](index_t face) -> const SurfaceMap* {
        if (face == 0 || face > m->size()) return nullptr;
        return (*m)[face - 1].get();
    };
    return PipelineInput{geometry, std::move(lookup), std::move(faces)};
}

std::vector<std::string> PreparedModel::report_lines() const {
    std::vector<std::string> lines;
    lines.push_back(fmt::format("{} tube{} found", tubes.tubes.size(), tubes.tubes.size() == 1 ? "" : "s"));
    for (std::size_t t = 0; t < tubes.tubes.size(); ++t) {
        const TubeInfo& tube = tubes.tubes[t];
        lines.push_back(fmt::format("  tube {}: faces {}, radius {:.6g}, length {:.6g}, hosts face_{} and face_{}",
                                    t + 1, join(tube.faces), tube.radius_max, tube.length, tube.hosts[0],
                                    tube.hosts[1]));
    }
    for (const TubeRejection& r : tubes.rejected) {
        if (r.faces.empty())
            lines.push_back(fmt::format("  not a tube: {}", r.reason));
        else
            lines.push_back(fmt::format("  not a tube (faces {}): {}", join(r.faces), r.reason));
    }
    lines.push_back(fmt::format("sizes: S = {:.6g}, St = {:.6g} (from S = {:.6g} ({}), St = {:.6g} ({}))", plan.size,
                                plan.sweep_size, plan.initial_size, plan.size_source, plan.initial_sweep_size,
                                plan.sweep_source));
    for (const SizeChange& c : plan.changes)
        lines.push_back(fmt::format("  {}: St {:.6g} -> {:.6g}, S {:.6g} -> {:.6g}: {}", c.rule, c.old_sweep_size,
                                    c.new_sweep_size, c.old_size, c.new_size, c.reason));
    for (const std::string& w : plan.warnings) lines.push_back("  warning: " + w);
    return lines;
}

}  // namespace tubemesh::geom
