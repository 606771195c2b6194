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

std::vector<std::string> plan_warnings(const TubeSearch& tubes, const SizePlan& plan,
                                       const std::vector<RingDrop>& dropped) {
    std::vector<std::string> w;
    if (tubes.tubes.empty() && dropped.empty())
        w.push_back("no tubular hole found in the solid: no hex rings or pyramids, the volume is meshed with "
                    "tetrahedra only");
    // A hole that lost its ring says so by name: the tets are a fallback, not what was asked for.
    for (const RingDrop& d : dropped) w.push_back(d.warning);
    for (const TubeInfo& t : tubes.tubes)
        if (t.stop)
            w.push_back(fmt::format("the pipe of wall faces {} comes too near at one spot ({}): its hex ring stops on a "
                                    "cross-section before it ({:.0f}% of its length), and its wall beyond (faces {}) is "
                                    "meshed with tetrahedra; for a ring along all of it, move the pipe",
                                    join(whole_tube(t).faces), t.stop->reason, 100 * t.length / t.stop->length,
                                    join(t.stop->beyond)));
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
    for (const TubeInfo& t : tubes.tubes)
        if (t.stop) holes.rejected.push_back({t.stop->beyond, "beyond where its ring stops", 2, false, t.radius_min});
    return holes;
}

// The tubes the caller stopped (PrepareOptions::stops) cut back to their stretch: each stop's
// closed edge, found on one tube's wall near the cross-section's centre.
void apply_stops(const Model& model, const std::vector<PrepareOptions::StopAt>& stops, TubeSearch& tubes) {
    for (const PrepareOptions::StopAt& s : stops)
        for (TubeInfo& t : tubes.tubes) {
            if (t.stop) continue;
            const int edge = stop_edge_at(model, t.faces, s.centre, s.radius);
            if (edge == 0) continue;
            t = stopped_tube(model, t, edge, s.keep);
            t.stop->reason = s.reason;
            break;
        }
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

// Each ring that stops prepares the model again, split once more: a few are worth it.
constexpr std::size_t kMostRingStops = 4;

// Tube t, dropped for a spot, keeping its ring on its longer stretch with room: the model with
// its wall split before the spot, prepared; nullopt when no stretch is worth a ring or the split
// fails (the tube is then dropped whole).
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
    const std::optional<RingCut> cut = ring_cut(tube, clearance, need);
    if (!cut) return std::nullopt;
    try {
        auto split = std::make_shared<const Model>(
            split_wall(model, wall_face_at(model, tube.faces, cut->centre), cut->centre, cut->tangent));
        const int splits = static_cast<int>(options.stops.size());
        PrepareOptions o = options;
        o.drop = drops_on_split(model, *split, splits, options.drop);
        // The drop's face ids are this model's, not the split's: the reason names none.
        const std::string how_near = drop.reason.substr(0, drop.reason.find(" from "));
        // The face the clearance was measured to may be another pipe's wall: where pipes touch,
        // the wall beyond the spot of the one that stopped first.
        const bool pipe_wall = std::any_of(tubes.tubes.begin(), tubes.tubes.end(), [&](const TubeInfo& u) {
            const auto has = [&](const std::vector<int>& f) { return std::binary_search(f.begin(), f.end(), plan.dcb_face); };
            return has(u.faces) || (u.stop && has(u.stop->beyond));
        });
        o.stops.push_back({cut->centre, cut->keep, tube.radius_max,
                           fmt::format("{} from {}", how_near, near_pipe || pipe_wall ? "another pipe" : "a face")});
        PreparedModel p = prepare_unguarded(*split, o);
        // Every ring stopped so far still stops (none dropped after all), or this split is no use.
        if (std::count_if(p.tubes.tubes.begin(), p.tubes.tubes.end(), [](const TubeInfo& x) { return x.stop.has_value(); }) <
            static_cast<std::ptrdiff_t>(o.stops.size()))
            return std::nullopt;
        if (!p.split) p.split = std::move(split);
        p.splits = std::max(p.splits, splits + 1);
        return p;
    } catch (const Error&) {
        return std::nullopt;
    } catch (const Standard_Failure&) {  // a split OpenCASCADE could not make: the tube goes whole
        return std::nullopt;
    }
}

// Per pipe: a ring at the plan's St (or the caller's per tube), or none and why.
std::vector<RingCoverage> ring_coverage(const Model& model, const TubeSearch& tubes, const SizePlan& plan,
                                        const std::vector<RingDrop>& dropped, const PrepareOptions& options) {
    std::vector<RingCoverage> out;
    const std::vector<double>& given = options.discretize.tube_sweep_size;
    for (std::size_t t = 0; t < tubes.tubes.size(); ++t) {
        const TubeInfo& tube = tubes.tubes[t];
        const double st = t < given.size() && given[t] > 0 ? given[t] : plan.sweep_size;
        RingCoverage c{tube.faces, static_cast<int>(t + 1),
                       2 * std::numbers::pi * (tube.radius_min + tube.radius_max) / 2 * tube.length, 1.0, st, st, {}};
        if (tube.stop) {
            c.faces = whole_tube(tube).faces;
            c.share = tube.length / tube.stop->length;
            c.wall_area /= c.share;
            c.ring_length = tube.length;
            c.length = tube.stop->length;
            c.reason = fmt::format("ring stops before a spot {}", tube.stop->reason);
        } else if (!plan.changes.empty())
            c.reason = fmt::format("St cut by {}: {}", sizing_rule_name(plan.changes.back().rule), plan.changes.back().reason);
        out.push_back(std::move(c));
    }
    for (const RingDrop& d : dropped) {
        RingCoverage c{d.length > 0 ? d.faces : curved_faces(model, d.faces), 0, 0, 0, 0, 0, d.reason};
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
        // Else pipe walls that meet: they do at a sharp angle where pipes of one size cross or overlap.
        for (const RingDrop& d : p.dropped)
            if (p.flat_tets_cause.empty() && d.length == 0)
                p.flat_tets_cause = fmt::format("pipe walls that meet (faces {}), at an angle that can be sharp there",
                                                join(d.faces));
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
