#include "job/quality_measures.hpp"

namespace tubemesh::job {

namespace {

// The classes of QualitySummary (the paper's Fig. 7 for the paper's measures).
constexpr QualityMeasure kMeasures[] = {
    {CellKind::Tet, CellMeasure::Primary, "tet", "collapse", "tet collapse", 0, 1, true},
    {CellKind::Tet, CellMeasure::ScaledJacobian, "tet", "scaled_jacobian", "tet scaled Jacobian (Verdict)", 0, 1, true},
    {CellKind::Tet, CellMeasure::MinDihedral, "tet", "min_dihedral_degrees", "tet smallest dihedral angle (degrees)", 0,
     90, true},
    {CellKind::Tet, CellMeasure::AspectRatio, "tet", "aspect_ratio", "tet aspect ratio (Verdict)", 1, 4, false},
    {CellKind::Pyramid, CellMeasure::Primary, "pyramid", "scaled_jacobian", "pyramid scaled Jacobian (Verdict)", 0, 1,
     true},
    {CellKind::Hex, CellMeasure::Primary, "hex", "scaled_jacobian", "hex scaled Jacobian J_m", 0, 1, true},
    {CellKind::Hex, CellMeasure::Condition, "hex", "condition", "hex condition number", 1, 4, false},
    {CellKind::Hex, CellMeasure::ScaledJacobian, "hex", "verdict_scaled_jacobian", "hex scaled Jacobian (Verdict)", 0,
     1, true},
};

}  // namespace

std::span<const QualityMeasure> quality_measures() { return kMeasures; }

const QualityMeasure& primary_measure(CellKind kind) {
    for (const QualityMeasure& m : kMeasures)
        if (m.kind == kind) return m;
    throw Error("no quality measure for a cell kind");
}

}  // namespace tubemesh::job
