#include "job/mesh_report.hpp"

#include <fmt/format.h>

#include "engine/io/mesh_notes.hpp"
#include "engine/mesh/surface_groups.hpp"
#include "job/paper_table.hpp"
#include "job/quality_table.hpp"

namespace tubemesh::job {

namespace {

bool whole(double x) { return x >= 0 && x < 1e15 && x == static_cast<double>(static_cast<long long>(x)); }

std::string count_text(const std::pair<std::string, double>& c) {
    if (whole(c.second)) return fmt::format("{} {}", static_cast<long long>(c.second), c.first);
    return fmt::format("{} {:.4g}", c.first, c.second);
}

double phase_seconds(const geom::MeshRun& run, const char* name) {
    for (const PhaseReport& p : run.result.phases)
        if (p.name == name) return p.seconds;
    return -1;
}

nlohmann::json pairs_json(const std::vector<std::pair<std::string, double>>& pairs) {
    nlohmann::json o = nlohmann::json::object();
    for (const auto& [name, value] : pairs) o[name] = value;
    return o;
}

KindTimes kind_times(const geom::MeshRun& run) {
    KindTimes times;
    times.tet = phase_seconds(run, "tets");
    times.pyramid = phase_seconds(run, "pyramids");
    times.hex = phase_seconds(run, "sweep");
    return times;
}

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// Per surface group: where it is (alias, CAD kind, measured area, centroid, normal if flat).
nlohmann::json groups_json(const HybridMesh& m, const MeshDescription& d) {
    const std::vector<SurfaceGroupGeometry> geometry = surface_group_geometry(m);
    nlohmann::json groups = nlohmann::json::array();
    for (std::size_t g = 0; g < geometry.size(); ++g) {
        const SurfaceGroupInfo* info = d.group(g);
        nlohmann::json j = {{"name", m.surface_group_names[g]},
                            {"where", io::group_role(m, &d, g)},
                            {"surface_kind", info ? info->surface_kind : ""},
                            {"faces", geometry[g].faces},
                            {"area", geometry[g].area},
                            {"centroid", vec_json(geometry[g].centroid)}};
        if (geometry[g].flat) j["normal"] = vec_json(geometry[g].normal);
        groups.push_back(std::move(j));
    }
    return groups;
}

// Per pipe: wall area, share under a hex ring, the ring's thickness range, why thinned or none.
nlohmann::json pipes_json(const std::vector<geom::RingCoverage>& pipes) {
    nlohmann::json out = nlohmann::json::array();
    for (const geom::RingCoverage& p : pipes) {
        nlohmann::json j = {{"faces", p.faces},
                            {"wall_area", p.wall_area},
                            {"ring_share", p.share},
                            {"ring_thickness", {{"min", p.thinnest}, {"max", p.thickest}}},
                            {"reason", p.reason}};
        if (p.tube > 0) j["ring"] = "pipe_" + std::to_string(p.tube);
        // A ring that stops inside the solid: the stretch of centre line under it.
        if (p.length > 0) j["ring_stretch"] = {{"ring_length", p.ring_length}, {"length", p.length}};
        out.push_back(std::move(j));
    }
    return out;
}

}  // namespace

std::vector<std::string> group_lines(const geom::MeshRun& run) {
    return io::mesh_notes(run.result.mesh, &run.result.description);
}

std::vector<std::string> phase_lines(const geom::MeshRun& run) {
    std::vector<std::string> lines;
    for (const PhaseReport& p : run.result.phases) {
        std::string text;
        for (const auto& c : p.counts) text += (text.empty() ? "" : ", ") + count_text(c);
        std::string stats;
        for (const auto& s : p.statistics) stats += (stats.empty() ? "" : ", ") + fmt::format("{} {:.4g}", s.first, s.second);
        if (!stats.empty()) text += (text.empty() ? "" : "; ") + stats;
        lines.push_back(fmt::format("{:<10} {:8.3f} s  {}", p.name, p.seconds, text));
    }
    return lines;
}

std::string run_table(const geom::MeshRun& run) {
    const PipelineResult& r = run.result;
    std::string table = format_run_table(r.quality, r.mesh.point_count(), kind_times(run), r.seconds);
    if (const PaperExample* paper = paper_example(run.name))
        table += "\n" + format_paper_table(*paper, paper_rows(*paper, r.quality, r.mesh.point_count()));
    return table;
}

std::vector<TableRow> run_table_rows(const geom::MeshRun& run) {
    const PipelineResult& r = run.result;
    std::vector<TableRow> rows = table_rows(r.quality, r.mesh.point_count(), kind_times(run));
    for (TableRow& row : total_rows(r.quality, r.seconds)) rows.push_back(std::move(row));
    return rows;
}

nlohmann::json run_json(const geom::MeshRun& run, const std::vector<std::string>& outputs) {
    const PipelineResult& r = run.result;
    const HybridMesh& m = r.mesh;
    nlohmann::json phases = nlohmann::json::array();
    for (const PhaseReport& p : r.phases)
        phases.push_back({{"name", p.name},
                          {"seconds", p.seconds},
                          {"counts", pairs_json(p.counts)},
                          {"statistics", pairs_json(p.statistics)}});
    nlohmann::json violations = nlohmann::json::array();
    for (const Violation& v : r.check.violations)
        violations.push_back({{"kind", violation_name(v.kind)}, {"count", v.count}});
    const index_t cells = m.cell_count();
    nlohmann::json node_sets = nlohmann::json::object();
    for (const NamedNodeSet& n : r.description.node_sets) node_sets[n.name] = n.nodes.size();
    nlohmann::json report = {{"source", run.source},
                             {"format", run.format},
                             {"name", run.name},
                             {"stage", stage_name(r.reached)},
                             {"sizes", {{"S", run.size}, {"St", run.sweep_size}}},
                             {"tubes", run.tubes},
                             {"pipes", pipes_json(run.coverage)},
                             {"ring_share", geom::ring_share(run.coverage)},
                             {"nodes", m.point_count()},
                             {"hexes", m.cell_count(CellKind::Hex)},
                             {"pyramids", m.cell_count(CellKind::Pyramid)},
                             {"tets", m.cell_count(CellKind::Tet)},
                             {"boundary_triangles", m.face_count(FaceKind::Tri)},
                             {"boundary_quads", m.face_count(FaceKind::Quad)},
                             {"length_unit", r.description.length_unit},
                             {"regions", m.region_names},
                             {"surface_groups", groups_json(m, r.description)},
                             {"node_sets", node_sets},
                             {"phases", phases},
                             {"total_seconds", r.seconds},
                             {"elements_per_second", r.seconds > 0 ? cells / r.seconds : 0.0},
                             {"quality", quality_json(r.quality)},
                             {"check",
                              {{"interior_faces", r.check.interior_faces},
                               {"free_faces", r.check.boundary_faces},
                               {"volume", r.check.volume},
                               {"violations_expected_at_this_stage", violations}}},
                             {"warnings", r.warnings},
                             {"model", run.model_lines},
                             {"outputs", outputs}};
    if (!r.description.region_surfaces.empty()) {
        nlohmann::json surfaces = nlohmann::json::array();
        for (const RegionSurface& s : r.description.region_surfaces) {
            std::vector<std::string> groups;
            for (index_t g : s.groups) groups.push_back(m.surface_group_names[g]);
            surfaces.push_back({{"name", s.name}, {"region", m.region_names[s.region]}, {"groups", groups}});
        }
        report["region_surfaces"] = surfaces;
    }
    if (const PaperExample* paper = paper_example(run.name))
        report["paper_table1"] = paper_table_json(*paper, paper_rows(*paper, r.quality, m.point_count()));
    return report;
}

}  // namespace tubemesh::job
