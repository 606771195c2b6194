#include "job/quality_table.hpp"

#include <fmt/format.h>

namespace tubemesh::job {

namespace {

void add_measure_rows(std::vector<TableRow>& rows, const char* kind, const char* measure, const MeasureSummary& m,
                      bool with_count, double seconds = -1) {
    if (with_count) rows.push_back({kind, "Num. element", fmt::format("{}", m.count)});
    if (with_count && seconds >= 0) rows.push_back({"", "Wall time", fmt::format("{:.3f} s", seconds)});
    if (m.count == 0) return;
    rows.push_back({"", fmt::format("Min. {}", measure), fmt::format("{:.6f}", m.min)});
    rows.push_back({"", fmt::format("Avg. {}", measure), fmt::format("{:.6f}", m.mean)});
    rows.push_back({"", fmt::format("Max. {}", measure), fmt::format("{:.6f}", m.max)});
}

std::string histogram_line(const char* label, const MeasureSummary& m) {
    std::string line = fmt::format("{:<22}", label);
    for (index_t c : m.histogram) line += fmt::format(" {:>7}", c);
    return line + "\n";
}

nlohmann::json measure_json(const MeasureSummary& m) {
    return {{"count", m.count}, {"min", m.min},   {"mean", m.mean},
            {"max", m.max},     {"classes_lo", m.lo}, {"classes_hi", m.hi}, {"histogram", m.histogram}};
}

std::string rows_text(const std::vector<TableRow>& rows) {
    std::string out;
    for (const TableRow& r : rows) out += fmt::format("{:<18} {:<16} {:>12}\n", r.kind, r.label, r.value);
    return out;
}

std::string histograms(const QualitySummary& q) {
    std::string out;
    out += "\nShape metric classes (10 equal classes; Cond over [1, 4]):\n";
    if (q.tet_collapse.count) out += histogram_line("tet collapse", q.tet_collapse);
    if (q.pyramid_jacobian.count) out += histogram_line("pyramid scaled Jac.", q.pyramid_jacobian);
    if (q.hex_scaled_jacobian.count) out += histogram_line("hex J_m", q.hex_scaled_jacobian);
    if (q.hex_condition.count) out += histogram_line("hex Cond", q.hex_condition);
    if (q.tet_scaled_jacobian.count) out += histogram_line("tet SJ", q.tet_scaled_jacobian);
    if (q.tet_min_dihedral.count) out += histogram_line("tet dihedral [0, 90]", q.tet_min_dihedral);
    if (q.tet_aspect_ratio.count) out += histogram_line("tet aspect [1, 4]", q.tet_aspect_ratio);
    return out;
}

}  // namespace

const char* const kTableLegend =
    "(metric: the paper's, tet collapse and pyramid scaled Jacobian; SJ (scaled Jacobian) and aspect (aspect "
    "ratio): Verdict's, as ParaView's Mesh Quality computes them; dihedral: the smallest dihedral angle, degrees)";

std::vector<TableRow> table_rows(const QualitySummary& q, index_t nodes, const KindTimes& times) {
    std::vector<TableRow> rows;
    add_measure_rows(rows, "Tetrahedral mesh", "metric", q.tet_collapse, true, times.tet);
    add_measure_rows(rows, "", "SJ", q.tet_scaled_jacobian, false);
    add_measure_rows(rows, "", "dihedral", q.tet_min_dihedral, false);
    add_measure_rows(rows, "", "aspect", q.tet_aspect_ratio, false);
    add_measure_rows(rows, "Pyramidal mesh", "metric", q.pyramid_jacobian, true, times.pyramid);
    add_measure_rows(rows, "Hexahedral mesh", "J_m", q.hex_scaled_jacobian, true, times.hex);
    add_measure_rows(rows, "", "Cond", q.hex_condition, false);
    add_measure_rows(rows, "", "SJ", q.hex_verdict_jacobian, false);
    rows.push_back({"Nodes", "", fmt::format("{}", nodes)});
    return rows;
}

std::vector<TableRow> total_rows(const QualitySummary& q, double total_seconds) {
    const index_t cells = q.tet_collapse.count + q.pyramid_jacobian.count + q.hex_scaled_jacobian.count;
    return {{"Total time", "", fmt::format("{:.3f} s", total_seconds)},
            {"Elements / second", "", fmt::format("{:.0f}", total_seconds > 0 ? cells / total_seconds : 0.0)}};
}

std::string format_quality_table(const QualitySummary& q, index_t nodes) {
    return rows_text(table_rows(q, nodes)) + kTableLegend + "\n" + histograms(q);
}

std::string format_run_table(const QualitySummary& q, index_t nodes, const KindTimes& times, double total_seconds) {
    return rows_text(table_rows(q, nodes, times)) + kTableLegend + "\n" + rows_text(total_rows(q, total_seconds)) +
           histograms(q);
}

nlohmann::json quality_json(const QualitySummary& q) {
    return {{"tet_collapse", measure_json(q.tet_collapse)},
            {"pyramid_scaled_jacobian", measure_json(q.pyramid_jacobian)},
            {"hex_scaled_jacobian", measure_json(q.hex_scaled_jacobian)},
            {"hex_condition", measure_json(q.hex_condition)},
            {"tet_scaled_jacobian", measure_json(q.tet_scaled_jacobian)},
            {"tet_min_dihedral_degrees", measure_json(q.tet_min_dihedral)},
            {"tet_aspect_ratio", measure_json(q.tet_aspect_ratio)},
            {"hex_verdict_scaled_jacobian", measure_json(q.hex_verdict_jacobian)}};
}

}  // namespace tubemesh::job
