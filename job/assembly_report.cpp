#include "job/assembly_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "job/mesh_report.hpp"
#include "job/quality_table.hpp"

namespace tubemesh::job {

namespace {

double solids_volume(const geom::AssemblyRun& run) {
    double v = 0;
    for (const SolidSummary& s : run.solids) v += s.volume;
    return v;
}

double cad_volume(const geom::AssemblyRun& run, std::size_t k) {
    return k < run.cad_volumes.size() ? run.cad_volumes[k] : 0.0;
}

// A row's place in Table 1: its kind (the last one named above it) and its label.
using RowKey = std::pair<std::string, std::string>;

std::map<RowKey, std::string> values_by_row(const std::vector<TableRow>& rows) {
    std::map<RowKey, std::string> out;
    std::string kind;
    for (const TableRow& r : rows) {
        if (!r.kind.empty()) kind = r.kind;
        out[{kind, r.label}] = r.value;
    }
    return out;
}

std::vector<TableRow> solid_rows(const SolidSummary& s) {
    return table_rows(s.quality, s.nodes, {.tet = s.tet_seconds, .pyramid = s.pyramid_seconds});
}

}  // namespace

double volume_mismatch(const geom::AssemblyRun& run, const geom::MeshRun& whole) {
    const double sum = solids_volume(run);
    return sum > 0 ? std::abs(whole.result.check.volume - sum) / sum : 0;
}

std::vector<std::string> assembly_lines(const geom::AssemblyRun& run, const geom::MeshRun& whole) {
    // Table 1's rows down, a column per solid and the whole mesh's last; a solid's times are
    // its own pyramids and tets, the whole's those of the phases (solids side by side).
    const std::vector<TableRow> total = run_table_rows(whole);
    std::vector<std::map<RowKey, std::string>> columns;
    for (const SolidSummary& s : run.solids) columns.push_back(values_by_row(solid_rows(s)));
    std::vector<std::string> lines;
    std::string head = fmt::format("{:<18} {:<16}", "", "");
    for (const SolidSummary& s : run.solids) head += fmt::format(" {:>12}", s.name);
    lines.push_back(head + fmt::format(" {:>12}", "total"));
    std::string kind;
    for (const TableRow& r : total) {
        if (!r.kind.empty()) kind = r.kind;
        std::string line = fmt::format("{:<18} {:<16}", r.kind, r.label);
        for (const auto& c : columns) {
            const auto it = c.find({kind, r.label});
            line += fmt::format(" {:>12}", it == c.end() ? std::string("-") : it->second);
        }
        lines.push_back(line + fmt::format(" {:>12}", r.value));
    }
    std::string volume = fmt::format("{:<18} {:<16}", "Volume", "mesh");
    std::string cad = fmt::format("{:<18} {:<16}", "", "CAD");
    double cad_sum = 0;
    for (std::size_t k = 0; k < run.solids.size(); ++k) {
        volume += fmt::format(" {:>12.6g}", run.solids[k].volume);
        cad += fmt::format(" {:>12.6g}", cad_volume(run, k));
        cad_sum += cad_volume(run, k);
    }
    lines.push_back(volume + fmt::format(" {:>12.6g}", whole.result.check.volume));
    lines.push_back(cad + fmt::format(" {:>12.6g}", cad_sum));
    lines.push_back(fmt::format(
        "{} solids, {} shared faces ({} glued within {:.3g}), {} triangles on them (joint groups); the mesh's volume "
        "is the sum of its solids' to {:.2g}",
        run.solids.size(), run.report.shared_faces, run.report.glued_faces, run.report.glue_tolerance,
        run.shared_triangles, volume_mismatch(run, whole)));
    return lines;
}

nlohmann::json assembly_json(const geom::AssemblyRun& run, const geom::MeshRun& whole) {
    nlohmann::json solids = nlohmann::json::array();
    for (std::size_t k = 0; k < run.solids.size(); ++k) {
        const SolidSummary& s = run.solids[k];
        solids.push_back({{"name", s.name},
                          {"nodes", s.nodes},
                          {"hexes", s.hexes},
                          {"pyramids", s.pyramids},
                          {"tets", s.tets},
                          {"quality", quality_json(s.quality)},
                          {"volume", s.volume},
                          {"cad_volume", cad_volume(run, k)},
                          {"pyramid_seconds", s.pyramid_seconds},
                          {"tet_seconds", s.tet_seconds}});
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

}  // namespace tubemesh::job
