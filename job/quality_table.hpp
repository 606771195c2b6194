#pragma once
// Quality report laid out like the paper's Table 1: per kind the count, then min and mean of
// each measure (and max, which the paper omits), then the 10-class histograms of Fig. 7.
// The rows are built once and rendered as text (the CLI) or as an HTML table (html_report).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/quality/quality.hpp"

namespace tubemesh::job {

// The time of the phase that made each kind (tets: "tets", pyramids: "pyramids", hexes:
// "sweep"); negative when that phase did not run.
struct KindTimes {
    double tet = -1, pyramid = -1, hex = -1;
};

// One row of Table 1: the kind (only on a kind's first row), the row's name, its value as
// printed ("0.363000", "1.234 s", "13607").
struct TableRow {
    std::string kind, label, value;
};

// Table 1's rows: per kind its count, wall time (when known) and min / mean / max of each
// measure, then the nodes. The paper's row says CPU time; a parallel run is measured by the
// clock on the wall.
std::vector<TableRow> table_rows(const QualitySummary& q, index_t nodes, const KindTimes& times = {});
// What the measures' short names mean, printed under the rows.
extern const char* const kTableLegend;
// A run's last rows: the total time and elements per second (all cells over the total).
std::vector<TableRow> total_rows(const QualitySummary& q, double total_seconds);

std::string format_quality_table(const QualitySummary& q, index_t nodes);

// Table 1 of a meshing run: the rows with times, the legend, the totals, then the histograms.
std::string format_run_table(const QualitySummary& q, index_t nodes, const KindTimes& times, double total_seconds);
nlohmann::json quality_json(const QualitySummary& q);

}  // namespace tubemesh::job
