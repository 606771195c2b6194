#include "geom/sizing/sizing.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/core/types.hpp"
#include "geom/sizing/sizing_distances.hpp"

namespace tubemesh::geom {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDiagonalDivisor = 25;
constexpr double kSizeOverSweep = 1.3;
// A St from the sweep share stays within this many tube radii: a ring of 4 nodes thicker than that
// has hexes over the analysis limit Cond 4 (bench/results/tuning-notes.md).
constexpr double kShareMaxOverRadius = 12.5;

std::string tube_name(int index) { return "tube " + std::to_string(index + 1); }

std::string fmt(double x) {
    std::ostringstream s;
    s.precision(6);
    s << x;
    return s.str();
}

// Walls that touch measure a few 1e-13 either side of zero: a message says 0.
std::string distance_text(double d) { return fmt(std::max(0.0, d)); }

void check_user_size(double value, const char* name) {
    if (value < 0 || !std::isfinite(value))
        throw Error(std::string(name) + " must be a positive number, got " + fmt(value));
}

// Cuts St and records why. S stays (sizing.hpp says why we depart from the paper here).
void change(SizePlan& plan, std::string rule, double new_sweep, std::string reason) {
    SizeChange c;
    c.rule = std::move(rule);
    c.old_sweep_size = plan.sweep_size;
    c.old_size = plan.size;
    plan.sweep_size = new_sweep;
    c.new_sweep_size = plan.sweep_size;
    c.new_size = plan.size;
    c.reason = std::move(reason);
    plan.changes.push_back(std::move(c));
}

struct Extremes {
    double r_min = kInf, r_max = 0;
    double rc = kInf;
    int rc_tube = -1;
};

Extremes extremes(const std::vector<TubeInfo>& tubes) {
    Extremes e;
    for (std::size_t i = 0; i < tubes.size(); ++i) {
        e.r_min = std::min(e.r_min, tubes[i].radius_min);
        e.r_max = std::max(e.r_max, tubes[i].radius_max);
        if (tubes[i].min_curvature_radius < e.rc) {
            e.rc = tubes[i].min_curvature_radius;
            e.rc_tube = static_cast<int>(i);
        }
    }
    return e;
}

void apply_rules(SizePlan& plan, const Clearances& c, const Extremes& e) {
    if (!plan.local_ring && plan.sweep_size > 1.4 * c.dcb)
        change(plan, "1: St > 1.4 Dcb", 1.4 * c.dcb,
               tube_name(c.dcb_tube) + " is " + distance_text(c.dcb) + " from face " + std::to_string(c.dcb_face));
    if (!plan.local_ring && plan.sweep_size > 0.6 * c.dc)
        change(plan, "2: St > 0.6 Dc", 0.6 * c.dc,
               tube_name(c.dc_tube_a) + " and " + tube_name(c.dc_tube_b) + " are " + distance_text(c.dc) + " apart");
    if (plan.sweep_size > 0.8 * e.rc)
        change(plan, "3: St > 0.8 Rc", 0.8 * e.rc,
               "the centre line of " + tube_name(e.rc_tube) + " bends with radius " + fmt(e.rc));
}

void apply_guards(SizePlan& plan, const Clearances& c, const Extremes& e) {
    const double reach = kFaceRoom * plan.sweep_size;
    if (!plan.local_ring && reach >= c.dcb)
        change(plan, "guard: boundary", kGuardMargin * c.dcb / kFaceRoom,
               "a ring of thickness St plus the 2.2 St its pyramids need reaches " + fmt(reach) + " from " +
                   tube_name(c.dcb_tube) + ", but face " + std::to_string(c.dcb_face) + " is " + distance_text(c.dcb) + " away");
    const double gap = kTubeRoom * plan.sweep_size;
    if (!plan.local_ring && gap >= c.dc)
        change(plan, "guard: rings", kGuardMargin * c.dc / kTubeRoom,
               "two rings of thickness St and the 2.2 St their pyramids need take " + fmt(gap) + " between " +
                   tube_name(c.dc_tube_a) + " and " + tube_name(c.dc_tube_b) + ", which are " + distance_text(c.dc) + " apart");
    if (std::isfinite(e.rc)) {
        const double room = e.rc - e.r_max;
        if (room <= 0) {
            plan.warnings.push_back(tube_name(e.rc_tube) + " bends with radius " + fmt(e.rc) +
                                    ", not more than its radius " + fmt(e.r_max) + ": no swept ring fits");
        } else if (e.r_max + plan.sweep_size >= e.rc) {
            change(plan, "guard: bend", kGuardMargin * room,
                   "a ring of thickness St around " + tube_name(e.rc_tube) + " (radius " + fmt(e.r_max) +
                       ") would fold on the inside of its bend of radius " + fmt(e.rc));
        }
    }
}

// What bounds St for a rule or guard, in the clearance's own words.
std::string limit_reason(const std::string& rule, const Clearances& c, const Extremes& e) {
    const std::string why = rule == "1: St > 1.4 Dcb" || rule == "guard: boundary"
                                ? tube_name(c.dcb_tube) + " is " + distance_text(c.dcb) + " from face " + std::to_string(c.dcb_face)
                            : rule == "2: St > 0.6 Dc" || rule == "guard: rings"
                                ? tube_name(c.dc_tube_a) + " and " + tube_name(c.dc_tube_b) + " are " + distance_text(c.dc) +
                                      " apart"
                                : "the centre line of " + tube_name(e.rc_tube) + " bends with radius " + fmt(e.rc);
    return sizing_rule_name(rule) + ": " + why;
}

}  // namespace

std::string sizing_rule_name(const std::string& rule) {
    return !rule.empty() && std::isdigit(static_cast<unsigned char>(rule[0])) ? "rule " + rule : rule;
}

SizePlan plan_sizes(const Model& model, const std::vector<TubeInfo>& tubes, const SizingOptions& options) {
    check_user_size(options.size, "the mesh size S");
    check_user_size(options.sweep_size, "the sweep size St");
    SizePlan plan;
    const Extremes e = extremes(tubes);
    if (!(options.sweep_share >= 0 && options.sweep_share < 1 / kSizeOverSweep))
        throw Error("the sweep share St / S must be at least 0 and below " + fmt(1 / kSizeOverSweep) + ", got " +
                    fmt(options.sweep_share));
    const bool share = options.sweep_share > 0 && options.sweep_size <= 0 && !tubes.empty();
    if (options.sweep_size > 0) {
        plan.sweep_size = options.sweep_size;
        plan.sweep_source = "user";
    } else if (!tubes.empty() && !share) {
        plan.sweep_size = 2 * e.r_min;
        plan.sweep_source = "default: smallest tube diameter";
    } else if (tubes.empty()) {
        plan.sweep_source = "no tubes";
    }
    if (options.size > 0) {
        plan.size = options.size;
        plan.size_source = "user";
    } else {
        const double diagonal = box_diagonal(model, tubes);
        plan.size = std::max(diagonal / kDiagonalDivisor, kSizeOverSweep * plan.sweep_size);
        plan.size_source =
            plan.size == diagonal / kDiagonalDivisor ? "default: bounding-box diagonal / 25" : "default: 1.3 St";
    }
    if (share) {
        plan.sweep_size = std::min(options.sweep_share * plan.size, kShareMaxOverRadius * e.r_min);
        plan.sweep_source = plan.sweep_size < options.sweep_share * plan.size
                                ? "economy: " + fmt(kShareMaxOverRadius) + " tube radii"
                                : "economy: " + fmt(options.sweep_share) + " S";
    }
    plan.initial_size = plan.size;
    plan.initial_sweep_size = plan.sweep_size;
    plan.dc = kInf;
    plan.dcb = kInf;
    plan.rc = e.rc;
    plan.largest_sweep_size = kInf;
    if (tubes.empty()) return plan;

    const Clearances c = measure_clearances(model, tubes);
    plan.dc = c.dc;
    plan.dcb = c.dcb;
    plan.dc_tube_a = c.dc_tube_a;
    plan.dc_tube_b = c.dc_tube_b;
    plan.dcb_tube = c.dcb_tube;
    plan.dcb_face = c.dcb_face;
    plan.local_ring = options.local_ring;
    apply_rules(plan, c, e);
    apply_guards(plan, c, e);
    SizePlan widest;
    widest.sweep_size = kInf;
    widest.local_ring = plan.local_ring;
    apply_rules(widest, c, e);
    apply_guards(widest, c, e);
    plan.largest_sweep_size = widest.sweep_size;
    if (!widest.changes.empty()) plan.largest_sweep_limit = limit_reason(widest.changes.back().rule, c, e);
    if (options.size <= 0 && !plan.changes.empty()) {
        // The default S was max(diagonal / 25, 1.3 St): recompute it with the final St.
        const double diagonal = box_diagonal(model, tubes);
        plan.size = std::max(diagonal / kDiagonalDivisor, kSizeOverSweep * plan.sweep_size);
        plan.size_source =
            plan.size == diagonal / kDiagonalDivisor ? "default: bounding-box diagonal / 25" : "default: 1.3 St";
        plan.changes.back().new_size = plan.size;
    }
    return plan;
}

}  // namespace tubemesh::geom
