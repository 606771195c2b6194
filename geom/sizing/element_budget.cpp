#include "geom/sizing/element_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "engine/pipeline/element_cap.hpp"
#include "engine/sweep/ring_dimensions.hpp"

namespace tubemesh::geom {

namespace {

double tube_length(const std::vector<TubeExtent>& tubes) {
    double len = 0;
    for (const TubeExtent& t : tubes) len += t.length;
    return len;
}

// The smallest x in [from, to] (to 1 %) where `fits` holds, given that it holds from there on;
// 0 when it does not hold at `to` (or, with to = +inf, at 2^200 from).
template <class Fits>
double smallest_fitting(double from, double to, Fits fits) {
    double hi = from;
    for (int i = 0; i < 200 && hi < to && !fits(hi); ++i) hi *= 2;
    hi = std::min(hi, to);
    if (!std::isfinite(hi) || !fits(hi)) return 0;
    double lo = from;
    while (hi > 1.01 * lo) {
        const double mid = std::sqrt(lo * hi);
        (fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

// The tubes as the sweep would make them at another St: n follows St unless the user gave it.
std::vector<TubeExtent> at_sweep_size(std::vector<TubeExtent> tubes, double sweep_size, int given_ring_nodes) {
    for (TubeExtent& t : tubes)
        if (given_ring_nodes <= 0 && t.mean_radius > 0) t.ring_nodes = circumferential_count(t.mean_radius, sweep_size);
    return tubes;
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
        // A wall quad under every pyramid; the ring's two ends on the host faces.
        e.quads += quads + 2.0 * t.ring_nodes * o.radial_layers;
    }
    // The tets that grade from the pyramids' apexes up to S come on top of the volume's.
    e.tets += kTetsPerRingQuadAtLeast * e.pyramids;
    return e;
}

double element_limit(const ElementBudget& budget) {
    if (budget.max_elements > 0) return budget.max_elements;
    const double memory = budget.memory.bytes > 0 ? budget.memory.bytes : usable_memory().bytes;
    return memory > 0 ? memory / kBytesPerElementAtLeast : INFINITY;
}

std::string element_limit_text(const ElementBudget& budget) {
    if (budget.max_elements > 0) return fmt::format("--max-elements {:.3g}", budget.max_elements);
    const UsableMemory memory = budget.memory.bytes > 0 ? budget.memory : usable_memory();
    if (!(memory.bytes > 0)) return "no limit (the system does not say how much memory there is)";
    return fmt::format("about {:.3g} elements in the {:.3g} GiB this process may use ({}; at {:.0f} bytes each; "
                       "--max-elements sets another limit)",
                       element_limit(budget), memory.bytes / (1024.0 * 1024 * 1024), memory.source,
                       kBytesPerElementAtLeast);
}

ElementEstimate check_element_budget(double volume, double area, const std::vector<TubeExtent>& tubes, double size,
                          double sweep_size, const ElementBudget& budget, const BudgetContext& context) {
    const double limit = element_limit(budget);
    const ElementEstimate e = estimate_elements(volume, area, tubes, size, sweep_size, budget);
    if (!exceeds_limit(e, limit)) return e;

    const std::string limit_text = element_limit_text(budget);
    // What the rings bring whatever S: their cells and faces and the tets that grade away from them.
    const double rings = estimate_elements(volume, area, tubes, INFINITY, sweep_size, budget).total();
    const auto fits_at_size = [&](double s) {
        return !exceeds_limit(estimate_elements(volume, area, tubes, s, sweep_size, budget), limit);
    };
    const double fitting_size = smallest_fitting(size, INFINITY, fits_at_size);
    if (fitting_size > 0 && e.total() - rings > rings)
        throw Error(fmt::format("the mesh size S = {:.6g} ({}) is too small for this solid ({}): the mesh would have "
                                "at least {:.3g} elements, more than {}; give --size {:.3g} or more (is the model "
                                "in the unit you meant?)",
                                size, source_note(context.size_source), context.extent, e.total(), limit_text,
                                rounded_up(fitting_size)));

    const std::string what =
        fmt::format("the mesh would have at least {:.3g} elements, {:.3g} of them in and beside the hex rings "
                    "(hexes {:.3g}, pyramids {:.3g}, their faces and the tets around them), more than {}",
                    e.total(), rings, e.hexes, e.pyramids, limit_text);
    const std::string or_more_elements =
        fmt::format("give --max-elements {:.3g} or more (the run needs at least that many){}", rounded_up(e.total()),
                    budget.max_elements > 0 ? "" : ", if the memory holds them");
    if (context.ring_nodes > 0)
        throw Error(fmt::format("--circ {} puts too many nodes around the tubes ({:.6g} long in all, {}): {}; give a "
                                "smaller --circ or leave it out, or {}",
                                context.ring_nodes, tube_length(tubes), context.extent, what, or_more_elements));

    // A larger St, if the rules accept one that fits: a given S stays (St at most S / 1.3, the
    // default's ratio), a default S grows with St.
    const double sweep_cap = context.size_source == "user" ? std::min(context.largest_sweep_size, size / 1.3)
                                                           : context.largest_sweep_size;
    const auto fits_at_sweep = [&](double st) {
        const std::vector<TubeExtent> t = at_sweep_size(tubes, st, context.ring_nodes);
        const double s = context.size_source == "user" ? size : std::max(size, 1.3 * st);
        return !exceeds_limit(estimate_elements(volume, area, t, s, st, budget), limit);
    };
    const double fitting_sweep = sweep_cap > sweep_size ? smallest_fitting(sweep_size, sweep_cap, fits_at_sweep) : 0;
    const std::string head = fmt::format("the sweep size St = {:.6g} ({}) is too small for tubes {:.6g} long in all "
                                         "({}): {}",
                                         sweep_size, source_note(context.sweep_source), tube_length(tubes),
                                         context.extent, what);
    if (fitting_sweep > 0)
        throw Error(fmt::format("{}; give --sweep-size {:.6g} or more{}, or {}", head,
                                // Three digits, unless rounding them up would pass what the rules accept.
                                rounded_up(fitting_sweep) <= sweep_cap ? rounded_up(fitting_sweep) : fitting_sweep,
                                std::isfinite(context.largest_sweep_size)
                                    ? fmt::format(" (the sizing rules accept up to {:.6g})", context.largest_sweep_size)
                                    : "",
                                or_more_elements));
    const std::string bound =
        sweep_cap <= sweep_size * 1.0001
            ? fmt::format("St cannot be larger here ({})", context.largest_sweep_limit.empty()
                                                                   ? "it must stay below S"
                                                                   : "sizing " + context.largest_sweep_limit)
            : fmt::format("no St the sizing rules accept (up to {:.6g}) fits", sweep_cap);
    throw Error(fmt::format("{}; {}: {}{}", head, bound, or_more_elements,
                            fitting_size > 0 ? fmt::format(", or give --size {:.3g} or more", rounded_up(fitting_size)) : ""));
}

}  // namespace tubemesh::geom
