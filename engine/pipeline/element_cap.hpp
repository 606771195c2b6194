#pragma once
// The element budget as a cap on what a run really makes. geom's estimate
// (geom/sizing/element_budget.hpp) is a lower bound and runs 1-4x under the real counts, so
// after each stage the pipeline adds the elements made so far to the estimate of the stages
// still to come, and stops as soon as that exceeds the limit: a run over the cap is refused
// before its costliest stage where the counts allow, and never returns a mesh over it. Only a
// limit given in elements (--max-elements) is a cap: the default, the memory's worth at a
// guessed size per element, refuses estimates, and a run out of memory ends with bad_alloc.
// Elements are cells and boundary faces, as a mesh file counts them.
#include <cmath>
#include <string>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

struct ElementCap {
    double limit = INFINITY;  // +inf (default): no cap
    std::string limit_text;   // the limit in the user's words: "--max-elements 8e+03", or the memory's
    // Lower bounds of what each kind will number when the run ends (geom's estimate).
    double tets = 0, triangles = 0, hexes = 0, pyramids = 0, quads = 0;
    // Tets the estimate counts per pyramid on top of the volume's: once the sweep tells how
    // many pyramids come, the tets' bound follows the real number.
    double tets_per_pyramid = 0;
};

// The share of the refined tets the tet step keeps at the least: its relaxation and optimisation
// remove a few per cent (3-2 flips and edge removals outnumber 2-3 flips), so 0.8 is a bound with
// room (bench/results/tuning-notes.md).
inline constexpr double kRefinedTetsKept = 0.8;

// Throws tubemesh::Error when, during the tet step's refinement, the elements of `mesh` plus
// kRefinedTetsKept of the `tets` refined so far exceed cap.limit: the run is stopped before
// the optimisation, and before its memory runs out.
void check_refining_tets(const HybridMesh& mesh, double tets, const ElementCap& cap);

// x rounded up to three significant digits: a figure of advice that must not fall short of x.
double rounded_up(double x);

// Cells and boundary faces of the mesh.
double element_count(const HybridMesh& mesh);

enum class Stage;  // engine/pipeline/pipeline.hpp

// Throws tubemesh::Error when the elements of `mesh`, made up to the end of `reached`, plus the
// estimate of the stages after it up to `until` exceed cap.limit. `outer_quads`: the rings' outer quads, each
// of which gets one pyramid (known after the sweep).
void check_element_cap(const HybridMesh& mesh, Stage reached, Stage until, double outer_quads,
                       const ElementCap& cap);

}  // namespace tubemesh
