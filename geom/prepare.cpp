#include "geom/prepare.hpp"

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <unordered_set>

#include "engine/core/timing.hpp"
#include "geom/engine_grid.hpp"
#include "geom/sizing/discretize.hpp"
#include "geom/sizing/gap_sizes.hpp"
#include "geom/model/face_properties.hpp"
#include "geom/sizing/geometry_diagnosis.hpp"
#include "geom/sizing/sizing_distances.hpp"
#include "geom/model/surface_map_occt.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/sizing/ring_stop_place.hpp"
#include "geom/sizing/junction.hpp"
#include "geom/tubes/ring_stop.hpp"
#include "geom/working_scale.hpp"

namespace tubemesh::geom {

namespace {

std::string join(const std::vector<int>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (i) s += ',';
        s += std::to_string(ids[i]);
    }
    return s;
}

std::string source_text(const std::string& source) { return source == "user" ? "given" : source; }

// Given sizes are honoured or refused (prepare.hpp).
void refuse_contradictory_sizes(const SizePlan& plan, const SizingOptions& given, bool has_tubes) {
    if (!has_tubes) return;
    if (given.sweep_size > 0 && plan.sweep_size < given.sweep_size && !plan.changes.empty()) {
        const SizeChange& c = plan.changes.front();
        throw Error(fmt::format(
            "the sweep size St = {:.6g} is too large for this model: {} ({}); give St = {:.6g} or less, or "
            "leave St out to let tubemesh choose",
            given.sweep_size, sizing_rule_name(c.rule), c.reason, plan.sweep_size));
    }
    if (!(plan.sweep_size < plan.size))
        throw Error(fmt::format("contradictory sizes: the sweep size St = {:.6g} ({}) must be smaller than the mesh "
                                "size S = {:.6g} ({}); give a larger S or a smaller St",
                                plan.sweep_size, source_text(plan.sweep_source), plan.size,
                                source_text(plan.size_source)));
}

// What the element bound is computed from: the solid's rough volume and non-wall area, and
// each tube's length, radius and nodes around at the plan's St.
struct BoundInputs {
    RoughMeasures measures;
    std::vector<TubeExtent> extents;
};

BoundInputs bound_inputs(const Model& model, const TubeSearch& tubes, const SizePlan& plan,
                         const PrepareOptions& options) {
    std::vector<int> walls;
    BoundInputs in;
    for (const TubeInfo& t : tubes.tubes) {
        walls.insert(walls.end(), t.faces.begin(), t.faces.end());
        in.extents.push_back({t.length, t.radius_max, tube_ring_nodes(t, plan.sweep_size, options.discretize.ring_nodes),
                              (t.radius_min + t.radius_max) / 2});
    }
    in.measures = rough_measures(model, walls);
    return in;
}

// The element budget (element_budget.hpp) on the planned sizes, before discretize allocates
// stations and edge points for them.
ElementEstimate refuse_oversized_run(const Model& model, const TubeSearch& tubes, const SizePlan& plan,
                          const PrepareOptions& options) {
    if (options.budget.max_elements < 0)
        throw Error(fmt::format("the element limit must be positive (0: this machine's memory), got {}",
                                options.budget.max_elements));
    const BoundInputs in = bound_inputs(model, tubes, plan, options);
    const BoundingBox b = non_wall_box(model, tubes.tubes);
    // A St the rules cut is no longer the default's: name the rule that set it.
    const std::string sweep_source =
        plan.changes.empty() ? plan.sweep_source : plan.sweep_source + ", cut by " + sizing_rule_name(plan.changes.back().rule);
    const BudgetContext context{plan.size_source,
                                sweep_source,
                                fmt::format("{:.6g} x {:.6g} x {:.6g} {}", b.max.x - b.min.x, b.max.y - b.min.y,
                                            b.max.z - b.min.z, model.report().length_unit),
                                options.discretize.ring_nodes,
                                plan.largest_sweep_size,
                                plan.largest_sweep_limit};
    return check_element_budget(in.measures.volume, in.measures.area, in.extents, plan.size, plan.sweep_size,
                                options.budget, context);
}

// Why a ring stops, for a warning: a spot with too little room, or the wall of another pipe it
// ends on (stop_before_junction's).
constexpr std::string_view kJunction = "the wall of another pipe";
constexpr std::string_view kBlindEnd = "its blind end";
bool at_junction(const TubeInfo::Stop& stop) {
    return stop.reason.find(kJunction) != std::string::npos || stop.reason == kBlindEnd;
}
std::string where_it_stops(const TubeInfo::Stop& stop) {
    if (stop.reason == kBlindEnd) return "ends blind in the solid";
    return at_junction(stop) ? fmt::format("meets {}", stop.reason)
                             : fmt::format("comes too near at one spot ({})", stop.reason);
}

std::vector<std::string> plan_warnings(const TubeSearch& tubes, const SizePlan& plan,
                                       const std::vector<RingDrop>& dropped) {
    std::vector<std::string> w;
    if (tubes.tubes.empty() && dropped.empty())
        w.push_back("no tubular hole found in the solid: no hex rings or pyramids, the volume is meshed with "
                    "tetrahedra only");
    // A hole that lost its ring says so by name: the tets are a fallback, not what was asked for.
    // Walls that meet between stretches with rings are told with those pipes, below.
    std::set<int> stretched;
    for (const TubeInfo& t : tubes.tubes)
        if (t.stop && t.stop->stretch_only) stretched.insert(t.stop->wall.begin(), t.stop->wall.end());
    for (const RingDrop& d : dropped)
        if (!std::all_of(d.faces.begin(), d.faces.end(), [&](int f) { return stretched.count(f) > 0; }))
            w.push_back(d.warning);
    for (std::size_t i = 0; i < tubes.tubes.size(); ++i) {
        const TubeInfo& t = tubes.tubes[i];
        if (!t.stop) continue;
        // A pipe with rings either side of its spot is told once, at its first ring.
        const auto same_pipe = [&](const TubeInfo& x) { return x.stop && x.stop->wall == t.stop->wall; };
        if (std::any_of(tubes.tubes.begin(), tubes.tubes.begin() + static_cast<std::ptrdiff_t>(i), same_pipe)) continue;
        double kept = 0;
        for (const TubeInfo& x : tubes.tubes) kept += same_pipe(x) ? x.length : 0.0;
        const bool both = kept > t.length;
        w.push_back(fmt::format("the pipe of wall faces {} {}: {} ({:.0f}% of its length), and its wall {} (faces {}) "
                                "is meshed with tetrahedra; for a ring along all of it, move the pipe",
                                join(t.stop->wall), where_it_stops(*t.stop),
                                both ? "its hex rings stop on cross-sections either side of it"
                                     : "its hex ring stops on a cross-section before it",
                                100 * kept / t.stop->length, both ? "between" : "beyond", join(t.stop->beyond)));
    }
    for (const std::string& x : plan.warnings) w.push_back(x);
    return w;
}

bool same_faces(const std::vector<int>& a, const std::vector<int>& b) { return a == b; }

// The tubes the caller drops whatever their room (the retry's) leave the search for `dropped`.
// A tube whose ring stopped and is dropped after all takes the wall beyond with it.
RingDrop with_beyond(const TubeInfo& t, RingDrop d) {
    if (!t.stop) return d;
    d.faces.insert(d.faces.end(), t.stop->beyond.begin(), t.stop->beyond.end());
    std::sort(d.faces.begin(), d.faces.end());
    d.length = t.stop->length;
    return d;
}

void drop_given(TubeSearch& tubes, const std::vector<RingDrop>& given, int splits, std::vector<RingDrop>& dropped) {
    for (const RingDrop& d : given)
        for (auto t = tubes.tubes.begin(); t != tubes.tubes.end() && d.splits == splits; ++t)
            if (same_faces(t->faces, d.faces)) {
                dropped.push_back(with_beyond(*t, {d.faces, t->radius_min, t->length, d.reason, d.warning}));
                tubes.tubes.erase(t);
                break;
            }
}

// A pipe's wall in a group the tube search rejected: its curved faces (a group that ran into the
// host along a tangent wall holds the host's flat faces too).
std::vector<int> curved_faces(const Model& model, const std::vector<int>& faces) {
    std::vector<int> out;
    for (int f : faces)
        if (!face_properties(model, f).planar) out.push_back(f);
    return out.empty() ? faces : out;
}

// The holes meshed with tets, for the gap sizes: the search's rejected groups and the tubes that
// lost their rings, each by its wall.
TubeSearch tet_holes(const Model& model, const TubeSearch& tubes, const std::vector<RingDrop>& dropped) {
    TubeSearch holes;
    for (TubeRejection r : tubes.rejected) {
        for (const RingDrop& d : dropped)
            if (d.length == 0 && same_faces(d.faces, r.faces)) r.faces = curved_faces(model, r.faces);
        holes.rejected.push_back(std::move(r));
    }
    for (const RingDrop& d : dropped)
        if (d.length > 0) holes.rejected.push_back({d.faces, d.reason, 2, false, d.radius});
    for (const TubeInfo& t : tubes.tubes) {
        if (!t.stop) continue;
        // The wall between the two rings of one pipe is one hole.
        const bool seen = std::any_of(holes.rejected.begin(), holes.rejected.end(),
                                      [&](const TubeRejection& r) { return r.faces == t.stop->beyond; });
        if (!seen) holes.rejected.push_back({t.stop->beyond, "beyond where its ring stops", 2, false, t.radius_min});
    }
    return holes;
}

// The stretch of a group of walls that meet (three or more loops) a stop cuts off, as a tube whose
// ring stops there (junction.hpp); nullopt when the stop is not on the group's walls or that side
// is no tube.
std::optional<TubeInfo> stretch_of_group(const Model& model, const std::vector<int>& group,
                                         const PrepareOptions::StopAt& s) {
    const int edge = stop_edge_at(model, group, s.centre, s.radius);
    if (edge == 0) return std::nullopt;
    std::optional<TubeInfo> t = stretch_tube(model, group, edge, s.keep);
    if (!t) return std::nullopt;
    for (const JunctionPipe& pipe : junction_pipes(model, group, {})) {
        if (!std::binary_search(pipe.faces.begin(), pipe.faces.end(), t->faces.front())) continue;
        TubeInfo::Stop stop;
        stop.edge = edge;
        stop.wall = pipe.faces;
        for (int f : pipe.faces)
            if (!std::binary_search(t->faces.begin(), t->faces.end(), f)) stop.beyond.push_back(f);
        stop.loop = t->loops[1];
        stop.host = t->hosts[1];
        stop.loop_length = t->loop_lengths[1];
        std::vector<double> along = pipe.open;
        along.insert(along.end(), pipe.junction.begin(), pipe.junction.end());
        const auto [lo, hi] = std::minmax_element(along.begin(), along.end());
        stop.length = along.empty() ? t->length : std::max(*hi - *lo, t->length);
        stop.centre_line = t->centre_line;
        stop.reason = s.reason;
        stop.stretch_only = true;
        t->stop = std::move(stop);
        return t;
    }
    return std::nullopt;
}

// Whether one of `tubes` has face `f` on its wall.
bool on_a_wall_of(const std::vector<TubeInfo>& tubes, int f) {
    return std::any_of(tubes.begin(), tubes.end(),
                       [&](const TubeInfo& t) { return std::binary_search(t.faces.begin(), t.faces.end(), f); });
}

// The tubes the caller stopped (PrepareOptions::stops) cut back to their stretch: each stop's
// closed edge, found on one tube's wall near the cross-section's centre. A tube stopped twice
// becomes two, one from each end, the second right after the first; the wall between is beyond both.
void apply_stops(const Model& model, const std::vector<PrepareOptions::StopAt>& stops, TubeSearch& tubes) {
    const std::vector<TubeInfo> found = std::move(tubes.tubes);
    std::vector<std::vector<TubeInfo>> stretches(found.size());
    std::vector<TubeInfo> met;  // stretches of walls that meet, after the found tubes
    for (const PrepareOptions::StopAt& s : stops) {
        bool done = false;
        for (std::size_t i = 0; i < found.size() && !done; ++i) {
            if (stretches[i].size() == 2) continue;
            const int edge = stop_edge_at(model, found[i].faces, s.centre, s.radius);
            if (edge == 0) continue;
            stretches[i].push_back(stopped_tube(model, found[i], edge, s.keep));
            stretches[i].back().stop->reason = s.reason;
            done = true;
        }
        for (std::size_t g = 0; g < tubes.rejected.size() && !done; ++g)
            if (std::optional<TubeInfo> t = stretch_of_group(model, tubes.rejected[g].faces, s)) {
                met.push_back(std::move(*t));
                done = true;
            }
    }
    // The wall between a pipe's stretches is beyond them all; the group keeps what none holds.
    for (TubeInfo& t : met) std::erase_if(t.stop->beyond, [&](int f) { return on_a_wall_of(met, f); });
    for (TubeRejection& r : tubes.rejected) std::erase_if(r.faces, [&](int f) { return on_a_wall_of(met, f); });
    std::erase_if(tubes.rejected, [](const TubeRejection& r) { return r.faces.empty() && r.loops > 2; });
    tubes.tubes.clear();
    for (std::size_t i = 0; i < found.size(); ++i) {
        if (stretches[i].empty()) {
            tubes.tubes.push_back(found[i]);
            continue;
        }
        for (TubeInfo& t : stretches[i])
            std::erase_if(t.stop->beyond, [&](int f) { return on_a_wall_of(stretches[i], f); });
        for (TubeInfo& t : stretches[i]) tubes.tubes.push_back(std::move(t));
    }
    for (TubeInfo& t : met) tubes.tubes.push_back(std::move(t));
}

// `faces` of `from` in `to`, the model split_wall made of it: those it kept, and the new ones.
std::vector<int> faces_after_split(const Model& from, const Model& to, const std::vector<int>& faces) {
    const std::vector<int> same = same_faces_in(from, to);
    std::vector<int> out;
    for (int f : faces)
        if (f >= 1 && f <= static_cast<int>(same.size()) && same[static_cast<std::size_t>(f - 1)] > 0)
            out.push_back(same[static_cast<std::size_t>(f - 1)]);
    for (int f = 1; f <= to.face_count(); ++f)
        if (std::find(same.begin(), same.end(), f) == same.end()) out.push_back(f);
    std::sort(out.begin(), out.end());
    return out;
}

// The caller's drops for the model `split_wall` made from `model` (after `splits` splits): those in
// `model`'s face ids move to the split's, those for later splits stay.
std::vector<RingDrop> drops_on_split(const Model& model, const Model& split, int splits, const std::vector<RingDrop>& given) {
    const std::vector<int> same = same_faces_in(model, split);
    std::vector<RingDrop> out;
    for (RingDrop d : given) {
        if (d.splits < splits) continue;
        if (d.splits == splits) {
            bool all = true;
            for (int& f : d.faces) {
                f = f >= 1 && f <= static_cast<int>(same.size()) ? same[static_cast<std::size_t>(f - 1)] : 0;
                all = all && f > 0;
            }
            if (!all) continue;
            std::sort(d.faces.begin(), d.faces.end());
            d.splits = splits + 1;
        }
        out.push_back(std::move(d));
    }
    return out;
}

PreparedModel prepare_unguarded(const Model& model, const PrepareOptions& options);
std::optional<PreparedModel> split_and_prepare(const Model& model, std::vector<int> walls, const std::vector<RingCut>& cuts,
                                               const std::vector<double>& radii, const std::string& reason,
                                               const PrepareOptions& options);

// Each ring that stops prepares the model again, split once more: a few are worth it. Eight lets
// four pipes each keep rings on both sides of a spot, or two crossing pipes all four of theirs.
constexpr std::size_t kMostRingStops = 8;

// Tube t, dropped for a spot, keeping a ring on each stretch with room (ring_cuts): the model with
// its wall split before the spot on each such side, prepared; nullopt when no stretch is worth a
// ring or a split fails (the tube is then dropped whole).
std::optional<PreparedModel> stop_before_spot(const Model& model, const TubeSearch& tubes, std::size_t t,
                                              const SizePlan& plan, const RingDrop& drop,
                                              const PrepareOptions& options) {
    const TubeInfo& tube = tubes.tubes[t];
    if (tube.stop) return std::nullopt;
    // From each centre-line point's wall to the face or pipe the drop names; a spot leaves less
    // room than a ring as thick as St (at most the radius) and its pyramids take.
    std::vector<double> clearance;
    const double st = std::min(std::max(plan.sweep_size, plan.initial_sweep_size), tube.radius_min);
    double need = kFaceRoom * st / kGuardMargin;
    const bool near_pipe = drop.reason.find("from the pipe") != std::string::npos;  // else near a face
    if (!near_pipe && plan.dcb_tube == static_cast<int>(t)) {
        const TopoDS_Face face = face_of(model, plan.dcb_face);
        for (const Vec3& c : tube.centre_line) {
            BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(c.x, c.y, c.z)).Vertex(), face);
            clearance.push_back(d.IsDone() ? d.Value() - tube.radius_max : 0.0);
        }
    } else if (near_pipe && plan.dc_tube_a >= 0 && plan.dc_tube_b >= 0) {
        const TubeInfo& other = tubes.tubes[static_cast<std::size_t>(
            plan.dc_tube_a == static_cast<int>(t) ? plan.dc_tube_b : plan.dc_tube_a)];
        need = kTubeRoom * st / kGuardMargin;
        for (const Vec3& c : tube.centre_line)
            clearance.push_back(polyline_distance({c}, other.centre_line) - tube.radius_max - other.radius_max);
    }
    std::vector<RingCut> cuts = ring_cuts(tube, clearance, need);
    // Past the limit the longer stretch alone keeps its ring.
    if (options.stops.size() + cuts.size() > kMostRingStops) cuts.resize(1);
    // The drop's face ids are this model's, not the split's: the reason names none.
    const std::string how_near = drop.reason.substr(0, drop.reason.find(" from "));
    // The face the clearance was measured to may be another pipe's wall: where pipes touch, the
    // wall beyond the spot of the one that stopped first.
    const bool pipe_wall = std::any_of(tubes.tubes.begin(), tubes.tubes.end(), [&](const TubeInfo& u) {
        const auto has = [&](const std::vector<int>& f) { return std::binary_search(f.begin(), f.end(), plan.dcb_face); };
        return has(u.faces) || (u.stop && has(u.stop->beyond));
    });
    return split_and_prepare(model, tube.faces, cuts, std::vector<double>(cuts.size(), tube.radius_max),
                             fmt::format("{} from {}", how_near, near_pipe || pipe_wall ? "another pipe" : "a face"),
                             options);
}

// The pipe wall `walls` split at each of `cuts` (of a pipe of radius radii[i]), each stretch it
// cuts off keeping a ring that stops there for `reason`, and the split model prepared; nullopt when
// there is no cut or a split fails (the pipe is then meshed as it would have been without them).
std::optional<PreparedModel> split_and_prepare(const Model& model, std::vector<int> walls, const std::vector<RingCut>& cuts,
                                               const std::vector<double>& radii, const std::string& reason,
                                               const PrepareOptions& options) {
    if (cuts.empty()) return std::nullopt;
    try {
        std::shared_ptr<const Model> split;
        int splits = static_cast<int>(options.stops.size());
        PrepareOptions o = options;
        for (std::size_t i = 0; i < cuts.size(); ++i) {
            const RingCut& cut = cuts[i];
            const Model& from = split ? *split : model;
            auto next = std::make_shared<const Model>(
                split_wall(from, wall_face_at(from, walls, cut.centre), cut.centre, cut.tangent));
            o.drop = drops_on_split(from, *next, splits++, o.drop);
            walls = faces_after_split(from, *next, walls);
            o.stops.push_back({cut.centre, cut.keep, radii[i], reason});
            split = std::move(next);
        }
        PreparedModel p = prepare_unguarded(*split, o);
        // Every ring stopped so far still stops (none dropped after all), or this split is no use.
        if (std::count_if(p.tubes.tubes.begin(), p.tubes.tubes.end(), [](const TubeInfo& x) { return x.stop.has_value(); }) <
            static_cast<std::ptrdiff_t>(o.stops.size()))
            return std::nullopt;
        if (!p.split) p.split = std::move(split);
        p.splits = std::max(p.splits, splits);
        return p;
    } catch (const Error&) {
        return std::nullopt;
    } catch (const Standard_Failure&) {  // a split OpenCASCADE could not make: the tube goes whole
        return std::nullopt;
    }
}

// The first tube that ends on a pipe wall (drop_branches' branch of a T-junction) keeping a ring
// that stops a diameter before the other wall: the model with its wall split there, prepared;
// nullopt when there is no such tube, its stretch is too short or the split fails.
std::optional<PreparedModel> stop_before_junction(const Model& model, const TubeSearch& tubes,
                                                  const std::vector<RingDrop>& dropped, const PrepareOptions& options) {
    if (!options.stop_rings || options.stops.size() >= kMostRingStops) return std::nullopt;
    std::set<int> walls;
    for (const TubeInfo& t : tubes.tubes) walls.insert(t.faces.begin(), t.faces.end());
    for (const RingDrop& d : dropped) walls.insert(d.faces.begin(), d.faces.end());
    for (const TubeInfo& t : tubes.tubes) {
        if (t.stop) continue;
        for (int end = 0; end < 2; ++end) {
            if (!walls.count(t.hosts[end]) || walls.count(t.hosts[1 - end])) continue;
            const std::optional<RingCut> cut = cut_before_end(t, end, edge_points(model, t.loops[end]));
            if (!cut) continue;
            std::optional<PreparedModel> p = split_and_prepare(model, t.faces, {*cut}, {t.radius_max},
                                                               fmt::format("face {}, {}", t.hosts[end], kJunction), options);
            if (p) return p;
        }
    }
    // Each cylinder of a group of walls that meet, cut before the junction on each side with an
    // open end, and of a blind hole before its bottom (junction.hpp). Walls that meet have three or
    // more loops, or two and cylinders of more than one axis (an L of drilled holes); a group with
    // one loop that lost its ring ran from a wall into the host's faces: a tangent wall, left whole.
    for (const TubeInfo& t : tubes.tubes)
        if (t.stop) {
            walls.insert(t.stop->wall.begin(), t.stop->wall.end());
            walls.insert(t.stop->beyond.begin(), t.stop->beyond.end());
        }
    for (const TubeRejection& r : tubes.rejected) {
        if (r.loops < 1 || r.crease) continue;
        const bool blind = r.loops == 1 && std::none_of(dropped.begin(), dropped.end(), [&](const RingDrop& d) {
                               return d.faces == r.faces;
                           });
        const std::vector<JunctionPipe> pipes = junction_pipes(model, r.faces, walls);
        if (r.loops < 3 && !blind && !(r.loops == 2 && pipes.size() > 1)) continue;
        std::vector<RingCut> cuts;
        std::vector<double> radii;
        for (const JunctionPipe& pipe : pipes)
            for (const RingCut& cut : junction_cuts(pipe, blind ? kBlindMargin : kJunctionMargin))
                if (options.stops.size() + cuts.size() < kMostRingStops) {
                    cuts.push_back(cut);
                    radii.push_back(pipe.radius);
                }
        std::optional<PreparedModel> p = split_and_prepare(model, r.faces, cuts, radii,
                                                           blind ? std::string(kBlindEnd) : std::string(kJunction), options);
        if (p) return p;
    }
    return std::nullopt;
}

// Per pipe: a ring at the plan's St (or the caller's per tube), or none and why.
std::vector<RingCoverage> ring_coverage(const Model& model, const TubeSearch& tubes, const SizePlan& plan,
                                        const std::vector<RingDrop>& dropped, const PrepareOptions& options) {
    std::vector<RingCoverage> out;
    const std::vector<double>& given = options.discretize.tube_sweep_size;
    // Walls that meet, cut into stretches with rings: the pipes' records hold their walls between.
    std::set<int> stretched;
    for (const TubeInfo& t : tubes.tubes)
        if (t.stop && t.stop->stretch_only) stretched.insert(t.stop->wall.begin(), t.stop->wall.end());
    for (std::size_t t = 0; t < tubes.tubes.size(); ++t) {
        const TubeInfo& tube = tubes.tubes[t];
        const double st = t < given.size() && given[t] > 0 ? given[t] : plan.sweep_size;
        RingCoverage c{tube.faces, static_cast<int>(t + 1),
                       2 * std::numbers::pi * (tube.radius_min + tube.radius_max) / 2 * tube.length, 1.0, st, st, {}};
        if (tube.stop) {
            c.faces = tube.stop->wall;
            c.share = tube.length / tube.stop->length;
            c.wall_area /= c.share;
            c.ring_length = tube.length;
            c.length = tube.stop->length;
            c.reason = fmt::format("ring stops before {}{}", at_junction(*tube.stop) ? "" : "a spot ", tube.stop->reason);
            // The second ring of a pipe, on the spot's other side, adds to the first's record.
            const auto first = std::find_if(out.begin(), out.end(), [&](const RingCoverage& x) { return x.faces == c.faces; });
            if (first != out.end()) {
                first->share += c.share;
                first->ring_length += c.ring_length;
                first->reason = fmt::format("rings stop either side of {}", at_junction(*tube.stop) ? "a junction" : "a spot " + tube.stop->reason);
                continue;
            }
        } else if (!plan.changes.empty())
            c.reason = fmt::format("St cut by {}: {}", sizing_rule_name(plan.changes.back().rule), plan.changes.back().reason);
        out.push_back(std::move(c));
    }
    for (const RingDrop& d : dropped) {
        RingCoverage c{d.length > 0 ? d.faces : curved_faces(model, d.faces), 0, 0, 0, 0, 0, d.reason};
        std::erase_if(c.faces, [&](int f) { return stretched.count(f) > 0; });
        if (c.faces.empty()) continue;
        if (d.length > 0)
            c.wall_area = 2 * std::numbers::pi * d.radius * d.length;
        else
            for (int f : c.faces) c.wall_area += face_properties(model, f).area;
        out.push_back(std::move(c));
    }
    std::sort(out.begin(), out.end(), [](const RingCoverage& a, const RingCoverage& b) { return a.faces < b.faces; });
    return out;
}

}  // namespace

ElementEstimate estimate_run_elements(const Model& model, const TubeSearch& tubes, const SizePlan& plan,
                                      const PrepareOptions& options) {
    const BoundInputs in = bound_inputs(model, tubes, plan, options);
    return estimate_elements(in.measures.volume, in.measures.area, in.extents, plan.size, plan.sweep_size,
                             options.budget);
}

PrepareOptions prepare_options(const MeshOptions& options) {
    PrepareOptions p;
    p.sizing.size = options.size;
    p.sizing.sweep_size = options.sweep_size;
    p.sizing.sweep_share = options.sweep_share;
    p.sizing.local_ring = options.local_ring;
    p.discretize.ring_nodes = options.circumferential;
    p.discretize.chordal = options.chordal;
    p.budget.max_elements = options.max_elements;
    p.budget.memory = options.memory;
    p.budget.sweep = options.sweep;
    p.size_growth = options.size_growth;
    p.grid_bits = options.grid_bits;
    p.progress = options.progress;
    return p;
}

namespace {

PreparedModel prepare_unguarded(const Model& model, const PrepareOptions& options) {
    if (options.discretize.ring_nodes < 0 || options.discretize.ring_nodes == 1 || options.discretize.ring_nodes == 2)
        throw Error(fmt::format("the number of nodes around a tube must be at least 3 (4 or more recommended), got {}",
                                options.discretize.ring_nodes));
    PreparedModel p;
    std::vector<HoleGroup> holes;  // holes meshed with tets: for the narrow gaps' warnings and sizes
    std::vector<std::string> gap_warnings;
    auto t0 = Clock::now();
    {
        PhaseProgress progress(options.progress, "tubes", 1);
        refuse_self_contact(model);
        p.tubes = find_tubes(model, options.tubes);
        apply_stops(model, options.stops, p.tubes);
        p.dropped = walls_without_ring(p.tubes, model.face_count());
        drop_given(p.tubes, options.drop, static_cast<int>(options.stops.size()), p.dropped);
        if (std::optional<PreparedModel> stopped = stop_before_junction(model, p.tubes, p.dropped, options))
            return std::move(*stopped);
        drop_branches(p.tubes, p.dropped);
        progress.finish();
    }
    p.phases.push_back({"tubes", seconds_since(t0),
                        {{"faces", double(model.face_count())},
                         {"tubes", double(p.tubes.tubes.size())},
                         {"not tubes", double(p.tubes.rejected.size())}},
                        {}});

    t0 = Clock::now();
    {
        PhaseProgress progress(options.progress, "sizes", 1);
        // Pipes too close for any ring worth making lose theirs one at a time, the closest first:
        // no St would help there, and the others' St is planned without them.
        for (;;) {
            p.plan = plan_sizes(model, p.tubes.tubes, options.sizing);
            RingDrop drop;
            const int t = tube_without_room(p.tubes, p.plan, thinnest_ring(options.sizing.local_ring),
                                              thinnest_ring_to_face(options.sizing.local_ring), drop);
            if (t < 0) break;
            if (drop.spot && options.stop_rings && options.stops.size() < kMostRingStops) {
                std::optional<PreparedModel> stopped =
                    stop_before_spot(model, p.tubes, static_cast<std::size_t>(t), p.plan, drop, options);
                if (stopped) return std::move(*stopped);
            }
            const TubeInfo& gone = p.tubes.tubes[static_cast<std::size_t>(t)];
            p.dropped.push_back(with_beyond(gone, std::move(drop)));
            p.tubes.tubes.erase(p.tubes.tubes.begin() + t);
        }
        refuse_contradictory_sizes(p.plan, options.sizing, !p.tubes.tubes.empty());
        const bool stops = std::any_of(p.tubes.tubes.begin(), p.tubes.tubes.end(), [](const TubeInfo& x) { return x.stop.has_value(); });
        holes = hole_groups(model, p.dropped.empty() && !stops ? p.tubes : tet_holes(model, p.tubes, p.dropped), p.plan.size);
        // A pipe without a ring was warned of already, narrow gap or not.
        const std::vector<HoleClearance> gaps = measure_hole_clearances(model, holes);
        narrow_gap_warnings(gaps, p.flat_tets_cause);
        // Else pipe walls that meet: they do at a sharp angle where pipes of one size cross or overlap;
        // dropped, or between stretches with rings (an L of drilled holes is no drop).
        const auto walls_meet = [&](const std::vector<int>& faces) {
            if (p.flat_tets_cause.empty())
                p.flat_tets_cause =
                    fmt::format("pipe walls that meet (faces {}), at an angle that can be sharp there", join(faces));
        };
        for (const RingDrop& d : p.dropped)
            if (d.length == 0) walls_meet(d.faces);
        for (const TubeInfo& t : p.tubes.tubes)
            if (t.stop && t.stop->stretch_only) walls_meet(t.stop->beyond);
        std::vector<HoleClearance> holes_only;
        for (const HoleClearance& h : gaps)
            if (std::none_of(p.dropped.begin(), p.dropped.end(), [&](const RingDrop& d) { return d.faces == h.hole_faces; }))
                holes_only.push_back(h);
        std::string cause;
        gap_warnings = narrow_gap_warnings(holes_only, cause);
        p.estimate = refuse_oversized_run(model, p.tubes, p.plan, options);
        // A limit in elements caps the real counts too. The memory's worth does not: the bytes an
        // element takes vary from run to run, and a run that fits in memory is not refused.
        const ElementEstimate& e = p.estimate;
        if (options.budget.max_elements > 0)
            p.cap = {element_limit(options.budget), element_limit_text(options.budget), e.tets, e.triangles, e.hexes,
                     e.pyramids, e.quads, kTetsPerRingQuadAtLeast};
        progress.finish();
    }
    PhaseReport sizes{"sizes", seconds_since(t0), {{"rule changes", double(p.plan.changes.size())}}, {}};
    sizes.statistics = {{"S", p.plan.size}};
    if (!p.tubes.tubes.empty()) sizes.statistics.push_back({"St", p.plan.sweep_size});
    p.phases.push_back(std::move(sizes));
    p.warnings = plan_warnings(p.tubes, p.plan, p.dropped);
    p.warnings.insert(p.warnings.end(), gap_warnings.begin(), gap_warnings.end());
    p.coverage = ring_coverage(model, p.tubes, p.plan, p.dropped, options);

    t0 = Clock::now();
    {
        PhaseProgress progress(options.progress, "discretize", 1);
        p.geometry = discretize(model, p.tubes.tubes, p.plan, options.discretize);
        p.maps = make_surface_maps(model);
        p.gap_sizes = gap_size_sources(model, holes, p.plan.size, options.size_growth);
        if (options.grid_bits > 0) {
            const BoundingBox box = model.bounds();
            const EngineGrid grid(std::hypot(box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z),
                                  options.grid_bits);
            snap(p.geometry, grid);
            snap(p.gap_sizes, grid);
            for (auto& map : p.maps) map = on_grid(std::move(map), grid);
        }
        progress.finish();
    }
    std::size_t edge_points = 0, stations = 0;
    for (const EdgePolyline& e : p.geometry.edges) edge_points += e.points.size();
    for (const TubeData& t : p.geometry.tubes) stations += t.stations.size();
    PhaseReport disc{"discretize", seconds_since(t0), {}, {}};
    disc.counts = {{"edges", double(p.geometry.edges.size())},
                   {"edge points", double(edge_points)},
                   {"tube stations", double(stations)}};
    std::size_t around = 0;  // n: the same for every tube unless the radii differ a lot
    for (const TubeData& t : p.geometry.tubes) around = around ? std::min(around, t.ring1.size()) : t.ring1.size();
    if (around) disc.counts.push_back({"nodes around (fewest)", double(around)});
    p.phases.push_back(std::move(disc));
    return p;
}

}  // namespace

PreparedModel prepare_model(const Model& model, const PrepareOptions& options) {
    // OpenCASCADE's exceptions are no std::exception: one escaping here would end the process.
    try {
        return prepare_unguarded(model, options);
    } catch (const Standard_Failure& e) {
        throw Error(fmt::format("internal error: OpenCASCADE failed while reading the model's tubes and sizes ({}: "
                                "\"{}\"); please report it with the CAD file",
                                e.DynamicType()->Name(), e.GetMessageString()));
    }
}

PipelineInput PreparedModel::pipeline_input() const {
    std::unordered_set<index_t> walls;
    for (const TubeData& t : geometry.tubes) walls.insert(t.wall_faces.begin(), t.wall_faces.end());
    std::vector<PipelineFace> faces;
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const index_t id = static_cast<index_t>(i + 1);
        faces.push_back({id, walls.count(id) > 0});
    }
    const auto* m = &maps;
    SurfaceLookup lookup = [m](index_t face) -> const SurfaceMap* {
        if (face == 0 || face > m->size()) return nullptr;
        return (*m)[face - 1].get();
    };
    return PipelineInput{geometry, std::move(lookup), std::move(faces), gap_sizes, {}, cap};
}

std::vector<std::string> PreparedModel::report_lines(int scale_exponent) const {
    const TubeSearch found = at_source_scale(tubes, scale_exponent);
    const SizePlan shown = at_source_scale(plan, scale_exponent);
    std::vector<std::string> lines;
    lines.push_back(fmt::format("{} tube{} found", found.tubes.size(), found.tubes.size() == 1 ? "" : "s") +
                    (dropped.empty() ? std::string()
                                     : fmt::format(" with a hex ring, {} pipe{} without", dropped.size(),
                                                   dropped.size() == 1 ? "" : "s")));
    for (std::size_t t = 0; t < found.tubes.size(); ++t) {
        const TubeInfo& tube = found.tubes[t];
        lines.push_back(fmt::format("  tube {}: faces {}, radius {:.6g}, length {:.6g}, hosts face_{} and face_{}",
                                    t + 1, join(tube.faces), tube.radius_max, tube.length, tube.hosts[0],
                                    tube.hosts[1]));
        if (const TubeInfo& raw = tubes.tubes[t]; raw.stop)
            lines.push_back(fmt::format("    ring stops at edge {} ({:.0f}% of its length): {}; faces {} beyond get tets",
                                        raw.stop->edge, 100 * raw.length / raw.stop->length, raw.stop->reason,
                                        join(raw.stop->beyond)));
        if (t < geometry.tubes.size() && !geometry.tubes[t].room.empty()) {
            const auto& th = geometry.tubes[t].room.thickness;
            lines.push_back(fmt::format("    ring thinned locally to {:.3g} (St {:.6g}) where a face or a tube is near",
                                        *std::min_element(th.begin(), th.end()), plan.sweep_size));
        }
    }
    for (const RingDrop& d : dropped) lines.push_back(fmt::format("  no hex ring (faces {}): {}", join(d.faces), d.reason));
    for (const TubeRejection& r : found.rejected) {
        if (r.faces.empty())
            lines.push_back(fmt::format("  not a tube: {}", r.reason));
        else
            lines.push_back(fmt::format("  not a tube (faces {}): {}", join(r.faces), r.reason));
    }
    lines.push_back(fmt::format("sizes: S = {:.6g}, St = {:.6g} (from S = {:.6g} ({}), St = {:.6g} ({}))", shown.size,
                                shown.sweep_size, shown.initial_size, shown.size_source, shown.initial_sweep_size,
                                shown.sweep_source));
    for (const SizeChange& c : shown.changes)
        lines.push_back(fmt::format("  {}: St {:.6g} -> {:.6g}, S {:.6g} -> {:.6g}: {}", c.rule, c.old_sweep_size,
                                    c.new_sweep_size, c.old_size, c.new_size, c.reason));
    for (const std::string& w : shown.warnings) lines.push_back("  warning: " + w);
    if (scale_exponent != 0) lines.push_back(working_scale_line(scale_exponent));
    return lines;
}

}  // namespace tubemesh::geom
