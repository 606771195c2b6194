#include "geom/sizing/element_budget.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "engine/sweep/ring_dimensions.hpp"

namespace tubemesh::geom {

namespace {

double tube_length(const std::vector<TubeExtent>& tubes) {
    double len = 0;
    for (const TubeExtent& t : tubes) len += t.length;
    return len;
}

// The smallest S (to 1 %) whose estimate fits `limit`, or 0 when the rings alone do not fit.
// The estimate falls as S grows, so bisection on a bracket that grows until it fits.
double smallest_fitting_size(double volume, double area, const std::vector<TubeExtent>& tubes, double size,
                             double sweep_size, const ElementBudget& budget, double limit) {
    auto fits = [&](double s) { return estimate_elements(volume, area, tubes, s, sweep_size, budget).total() <= limit; };
    double hi = size;
    for (int i = 0; i < 200 && !fits(hi); ++i) hi *= 2;
    if (!fits(hi)) return 0;
    double lo = size;
    while (hi > 1.01 * lo) {
        const double mid = std::sqrt(lo * hi);
        (fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

// The sources already read "default: ..." unless the user gave the size.
std::string source_note(const std::string& source) { return source == "user" ? "given" : source; }

}  // namespace

ElementEstimate estimate_elements(double volume, double area, const std::vector<TubeExtent>& tubes, double size,
                                  double sweep_size, const ElementBudget& budget) {
    ElementEstimate e;
    if (!(size > 0)) return e;
    e.tets = volume / (0.3 * size * size * size);
    e.triangles = area / (size * size);
    if (!(sweep_size > 0)) return e;
    const SweepOptions& o = budget.sweep;
    const std::vector<double> offsets = sweep::radial_offsets(sweep_size, o.radial_layers, o.grading);
    for (const TubeExtent& t : tubes) {
        const double step = sweep::axial_step(t.radius, offsets, t.ring_nodes, o.axial_aspect, o.max_condition);
        // One station fewer than the length allows: the sweep resamples its own centre line.
        const double quads = t.ring_nodes * std::max(0.0, std::floor(t.length / step) - 1);
        e.pyramids += quads;
        e.hexes += quads * o.radial_layers;
    }
    // The tets that grade from the pyramids' apexes up to S come on top of the volume's.
    e.tets += kTetsPerRingQuadAtLeast * e.pyramids;
    return e;
}

double physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? double(pages) * double(page) : 0;
}

double element_limit(const ElementBudget& budget) {
    if (budget.max_elements > 0) return budget.max_elements;
    const double memory = physical_memory_bytes();
    return memory > 0 ? memory / kBytesPerElementAtLeast : INFINITY;
}

ElementEstimate check_element_budget(double volume, double area, const std::vector<TubeExtent>& tubes, double size,
                          double sweep_size, const ElementBudget& budget, const BudgetContext& context) {
    const double limit = element_limit(budget);
    const ElementEstimate e = estimate_elements(volume, area, tubes, size, sweep_size, budget);
    if (!exceeds_limit(e, limit)) return e;

    const std::string limit_text =
        budget.max_elements > 0
            ? fmt::format("--max-elements {:.3g}", limit)
            : fmt::format("about {:.3g} elements in this machine's {:.1f} GiB of memory (at {:.0f} bytes each; "
                          "--max-elements sets another limit)",
                          limit, physical_memory_bytes() / (1024.0 * 1024 * 1024), kBytesPerElementAtLeast);
    const double fitting = smallest_fitting_size(volume, area, tubes, size, sweep_size, budget, limit);
    if (fitting > 0 && e.tets + e.triangles > e.hexes + e.pyramids)
        throw Error(fmt::format("the mesh size S = {:.6g} ({}) is too small for this solid ({}): the mesh would have "
                                "at least {:.3g} elements, more than {}; give --size {:.3g} or more (is the model "
                                "in the unit you meant?)",
                                size, source_note(context.size_source), context.extent, e.total(), limit_text,
                                fitting));
    if (context.ring_nodes > 0)
        throw Error(fmt::format("--circ {} puts too many nodes around the tubes ({:.6g} long in all, {}): the hex rings "
                                "alone would have at least {:.3g} elements, more than {}; give a smaller --circ or "
                                "leave it out",
                                context.ring_nodes, tube_length(tubes), context.extent, e.hexes + e.pyramids,
                                limit_text));
    throw Error(fmt::format("the sweep size St = {:.6g} ({}) is too small for tubes {:.6g} long in all ({}): the hex "
                            "rings alone would have at least {:.3g} elements, more than {}; give a larger "
                            "--sweep-size or --axial-aspect",
                            sweep_size, source_note(context.sweep_source), tube_length(tubes), context.extent,
                            e.hexes + e.pyramids, limit_text));
}

}  // namespace tubemesh::geom
