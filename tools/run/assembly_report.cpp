#include "tools/run/assembly_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tools/run/quality_table.hpp"

namespace tubemesh::run {

namespace {

double solids_volume(const geom::AssemblyRun& run) {
    double v = 0;
    for (const SolidSummary& s : run.solids) v += s.volume;
    return v;
}

std::string min_mean(const MeasureSummary& m) {
    return m.count > 0 ? fmt::format("{:.3f}/{:.3f}", m.min, m.mean) : std::string("-");
}

}  // namespace

double volume_mismatch(const geom::AssemblyRun& run, const geom::MeshRun& whole) {
    const double sum = solids_volume(run);
    return sum > 0 ? std::abs(whole.result.check.volume - sum) / sum : 0;
}

std::vector<std::string> assembly_lines(const geom::AssemblyRun& run, const geom::MeshRun& whole) {
    std::vector<std::string> lines;
    lines.push_back(fmt::format("{:<14} {:>7} {:>8} {:>9} {:>13} {:>13} {:>13} {:>12} {:>12} {:>8}", "solid", "hexes",
                                "pyramids", "tets", "tet min/mean", "pyr min/mean", "hex J min/mean", "volume",
                                "CAD volume", "time s"));
    double cad = 0;
    for (std::size_t k = 0; k < run.solids.size(); ++k) {
        const SolidSummary& s = run.solids[k];
        const double c = k < run.cad_volumes.size() ? run.cad_volumes[k] : 0;
        cad += c;
        lines.push_back(fmt::format("{:<14} {:>7} {:>8} {:>9} {:>13} {:>13} {:>13} {:>12.6g} {:>12.6g} {:>8.2f}", s.name,
                                    s.hexes, s.pyramids, s.tets, min_mean(s.quality.tet_collapse),
                                    min_mean(s.quality.pyramid_jacobian), min_mean(s.quality.hex_scaled_jacobian),
                                    s.volume, c, s.seconds));
    }
    const QualitySummary& q = whole.result.quality;
    const HybridMesh& m = whole.result.mesh;
    lines.push_back(fmt::format("{:<14} {:>7} {:>8} {:>9} {:>13} {:>13} {:>13} {:>12.6g} {:>12.6g}", "total",
                                m.cell_count(CellKind::Hex), m.cell_count(CellKind::Pyramid),
                                m.cell_count(CellKind::Tet), min_mean(q.tet_collapse), min_mean(q.pyramid_jacobian),
                                min_mean(q.hex_scaled_jacobian), whole.result.check.volume, cad));
    lines.push_back(fmt::format(
        "{} solids, {} shared faces ({} glued within {:.3g}), {} interior triangles on them; the mesh's volume is the "
        "sum of its solids' to {:.2g}",
        run.solids.size(), run.report.shared_faces, run.report.glued_faces, run.report.glue_tolerance,
        run.shared_triangles, volume_mismatch(run, whole)));
    return lines;
}

nlohmann::json assembly_json(const geom::AssemblyRun& run, const geom::MeshRun& whole) {
    nlohmann::json solids = nlohmann::json::array();
    for (std::size_t k = 0; k < run.solids.size(); ++k) {
        const SolidSummary& s = run.solids[k];
        solids.push_back({{"name", s.name},
                          {"hexes", s.hexes},
                          {"pyramids", s.pyramids},
                          {"tets", s.tets},
                          {"quality", quality_json(s.quality)},
                          {"volume", s.volume},
                          {"cad_volume", k < run.cad_volumes.size() ? run.cad_volumes[k] : 0.0},
                          {"seconds", s.seconds}});
    }
    return {{"solids", solids},
            {"shared_faces", run.report.shared_faces},
            {"glued_faces", run.report.glued_faces},
            {"glue_tolerance", run.report.glue_tolerance},
            {"shared_triangles", run.shared_triangles},
            {"volume", whole.result.check.volume},
            {"volume_sum_of_solids", solids_volume(run)},
            {"volume_mismatch", volume_mismatch(run, whole)}};
}

}  // namespace tubemesh::run
