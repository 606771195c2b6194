#pragma once
// A lower bound on a run's element count from its sizes alone, checked before any phase that
// allocates in proportion to it (prepare_model calls it right after planning S and St).
//
// Why: a size meant for another unit — a 4 m box that a STEP file declares as 4000 mm,
// meshed at --size 0.25 — asks for ~1e13 tetrahedra. Without the check the run fills the
// machine's memory for minutes and the kernel kills it, with no message and no file; with
// it the run stops at once with the size that would fit.
//
// The bound undercounts on purpose (each term below is at most what the phases make), so a
// run it refuses could not have finished in the memory it names:
//   tets       >= V / (0.3 S^3)    a tet's mean edge is at most 1.3 h <= 1.3 S after refinement
//                                  (regular tet of edge 1.3 S: 0.26 S^3); 8.1 per S^3 measured on
//                                  a uniform box, more near tubes
//              + 8 per ring quad   the tets grading from the pyramid layer up to S; 20-96 per
//                                  quad measured on the presets, 9.8 on two pipes 0.01 apart
//   triangles  >= A / S^2          faces other than tube walls; 2.3 per S^2 measured on a box
//   hexes      >= n L (floor(len / step) - 1), pyramids a 1/L of it: the ring's axial step
//                                  (engine/sweep/ring_dimensions.hpp) at the tube's largest radius;
//                                  bends only shorten it
//   quads      >= a wall quad per pyramid + 2 n L end quads per tube
// Being a lower bound, it cannot promise a run fits: the pipeline checks the real counts after
// each stage against the same limit (engine/pipeline/element_cap.hpp).
// No OpenCASCADE header here.
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/usable_memory.hpp"
#include "engine/sweep/sweep.hpp"

namespace tubemesh::geom {

// The fewest bytes per element at peak memory measured on the reference cases (185-501,
// README "Performance"), rounded down: the budget's memory figure.
inline constexpr double kBytesPerElementAtLeast = 150;

// The fewest tets per ring quad (pyramid) beyond the volume's V / (0.3 S^3), rounded down from
// the measurements above: a thin ring asks for millions of tets around it, not the 1e4 of V.
inline constexpr double kTetsPerRingQuadAtLeast = 8;

struct ElementBudget {
    // Refuse a run whose lower bound exceeds this many elements. 0 (default): what the memory
    // this process may use holds at kBytesPerElementAtLeast per element.
    double max_elements = 0;
    // That memory; bytes 0 (default): usable_memory() when the limit is asked for. The CLI reads
    // it before it lowers its own address-space limit.
    UsableMemory memory;
    // The run's hex ring options (layers L, grading, axial aspect, condition cap), for the hexes.
    SweepOptions sweep;
};

struct TubeExtent {
    double length = 0;       // of the centre line
    double radius = 0;       // the largest: the longest axial step
    int ring_nodes = 0;      // n around it
    double mean_radius = 0;  // what n follows from when St changes and n was not given
};

// Elements are cells and boundary faces, as a mesh file counts them.
struct ElementEstimate {
    double tets = 0, triangles = 0, hexes = 0, pyramids = 0, quads = 0;
    double total() const { return tets + triangles + hexes + pyramids + quads; }
};

// The lower bound for a solid of `volume` whose non-wall faces have `area`, at mesh size
// `size` (S) and sweep size `sweep_size` (St, unused without tubes).
ElementEstimate estimate_elements(double volume, double area, const std::vector<TubeExtent>& tubes, double size,
                                  double sweep_size, const ElementBudget& budget);

// What the check compares the estimate with: budget.max_elements, or the memory's worth.
double element_limit(const ElementBudget& budget);

// The limit in words: "--max-elements 8e+03", or the memory and where its figure comes from.
std::string element_limit_text(const ElementBudget& budget);

// The refusal rule itself, so that `inspect`'s "refuses these sizes" is the check's answer.
inline bool exceeds_limit(const ElementEstimate& e, double limit) { return e.total() > limit; }

// What the user gave, for the message: where S and St came from and the model's extent.
struct BudgetContext {
    std::string size_source;   // "user" or the default's formula (SizePlan::size_source)
    std::string sweep_source;  // likewise for St, with the rule that cut it when one did
    std::string extent;        // "4000 x 4000 x 4000 millimetre"
    int ring_nodes = 0;        // n around each tube when the user gave it (--circ), else 0
    // The largest St the sizing rules accept (+inf: unbounded) and what bounds it.
    double largest_sweep_size = INFINITY;
    std::string largest_sweep_limit;
};

// The estimate, or tubemesh::Error when it exceeds element_limit(budget): the message gives
// the bound, the limit and its source, and what would fit: the smallest S, the smallest St
// the rules accept, or, when neither can, the --max-elements the run needs at least.
ElementEstimate check_element_budget(double volume, double area, const std::vector<TubeExtent>& tubes, double size,
                          double sweep_size, const ElementBudget& budget, const BudgetContext& context);

}  // namespace tubemesh::geom
