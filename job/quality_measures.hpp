#pragma once
// Every per-cell quality measure the reports show, one entry each: what the HTML report draws a
// histogram of and what the Python module's `quality` holds. The measures themselves live in
// engine/quality (cell_measure); a new one there is one more entry here.
#include <span>
#include <vector>

#include "engine/quality/quality.hpp"

namespace tubemesh::job {

struct QualityMeasure {
    CellKind kind;
    CellMeasure measure;
    const char* kind_key;  // "tet", "pyramid", "hex"
    const char* key;       // "collapse", "scaled_jacobian", ...: the report's quality key without the kind
    const char* label;     // "tet collapse": the chart's title
    double lo, hi;         // the histogram's range (values outside fall in the end classes)
    bool higher_is_better;

    // One value per cell of `kind`, in cell order. Parallel over cells.
    std::vector<double> values(const HybridMesh& mesh) const { return cell_measure(mesh, kind, measure); }
};

std::span<const QualityMeasure> quality_measures();

// The measure that ranks a kind's cells (its first entry, the paper's): colours the 3D view and
// picks the worst elements. Every kind has one.
const QualityMeasure& primary_measure(CellKind kind);

}  // namespace tubemesh::job
