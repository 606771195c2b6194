#pragma once
// The paper's Table 1 beside a run's own figures when the solid is one of the paper's three
// examples, as `tubemesh make-block --preset paper-exN` builds them (the STEP file names its solid
// after the preset; the built-in block carries the name too). Rendered as text (the CLI), JSON
// (--report, Python) and the HTML page from one list of rows.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/quality/quality.hpp"

namespace tubemesh::job {

// One example's column of the paper's Table 1 (and its all-tet reference mesher's count).
struct PaperExample {
    const char* name;  // the preset: "paper-ex1", "paper-ex2", "paper-ex3"
    int number;        // 1, 2, 3
    index_t hexes, pyramids, tets, nodes;
    double tet_min, tet_mean, pyramid_min, pyramid_mean, jm_min, jm_mean, cond_min, cond_mean;
    index_t all_tet;  // tets of the all-tet mesh the paper compares with (Hypermesh)
};

// The example a solid of this name is; nullptr for any other name.
const PaperExample* paper_example(std::string_view solid_name);

// One line of the comparison: the paper's value, this mesh's (none where the paper's row has no
// counterpart here: the all-tet mesher). `whole`: a count, printed without decimals.
struct PaperRow {
    std::string key, label;
    double paper = 0;
    std::optional<double> ours;
    bool whole = false;
};

// Counts, nodes and Table 1's quality rows, then the all-tet reference. The pyramids are
// compared in different measures: the paper's Q_p, ours Verdict's scaled Jacobian (docs/architecture.md).
std::vector<PaperRow> paper_rows(const PaperExample& paper, const QualitySummary& q, index_t nodes);

// "Paper's Table 1, Example N, beside this mesh" and one line per row.
std::string format_paper_table(const PaperExample& paper, const std::vector<PaperRow>& rows);
// {"example": N, "preset": name, "rows": [{"key", "label", "paper", "this_mesh"}]}
nlohmann::json paper_table_json(const PaperExample& paper, const std::vector<PaperRow>& rows);

}  // namespace tubemesh::job
