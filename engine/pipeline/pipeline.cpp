#include "engine/pipeline/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>

#include "engine/core/timing.hpp"
#include "engine/surface/face_boundaries.hpp"
#include "engine/pipeline/pipe_stations.hpp"
#include "engine/pipeline/stage_check.hpp"
#include "engine/pipeline/surface_sizing.hpp"
#include "engine/sizing/thin_rings.hpp"
#include "engine/sizing/tet_size_caps.hpp"
#include "engine/core/parallelism.hpp"
#include "engine/surface/mesh_surfaces.hpp"

namespace tubemesh {

const char* stage_name(Stage s) {
    switch (s) {
        case Stage::Sweep: return "sweep";
        case Stage::Surface: return "surface";
        case Stage::Pyramids: return "pyramids";
        case Stage::Tets: return "tets";
    }
    return "?";
}

std::optional<Stage> stage_from_name(std::string_view name) {
    for (Stage s : kStages)
        if (name == stage_name(s)) return s;
    return std::nullopt;
}

namespace {

// Nodes of two joined rings closer than this share of St are one node (join_ring_ends).
constexpr double kRingJoinShare = 1e-6;

// Each ring's wall nodes at its two end stations, named after the pipe's wall group. A joined
// end is no rim; a pipe of joined rings has its two rims, the second named as the first is not.
// A stopped end's (TubeData::stops) is "<pipe>_ring_stop".
void add_rims(const SweepResult& sweep, const std::vector<RingJoin>& joins, const HybridMesh& mesh,
              MeshDescription& description) {
    const auto joined = [&](index_t tube, int end) {
        return std::any_of(joins.begin(), joins.end(), [&](const RingJoin& j) {
            return (j.tube_a == tube && j.end_a == end) || (j.tube_b == tube && j.end_b == end);
        });
    };
    for (const TubeRing& ring : sweep.rings) {
        const std::string& pipe = mesh.surface_group_names[ring.wall_group];
        for (int e = 0; e < 2; ++e) {
            if (joined(ring.tube, e)) continue;
            std::string name = pipe + (e == 0 ? "_inlet" : "_outlet");
            const auto named = [&](const std::string& n) {
                return std::any_of(description.node_sets.begin(), description.node_sets.end(),
                                   [&](const NamedNodeSet& s) { return s.name == n; });
            };
            if (named(name)) name = pipe + (e == 0 ? "_outlet" : "_inlet");
            // Where a ring stops the pipe goes on, meshed with tets: no end of the pipe.
            if (ring.stopped[static_cast<std::size_t>(e)]) name = pipe + "_ring_stop";
            NamedNodeSet rim{name, {}};
            const index_t station = e == 0 ? 0 : ring.stations - 1;
            for (index_t k = 0; k < ring.circumferential; ++k) rim.nodes.push_back(ring.node(station, 0, k));
            std::sort(rim.nodes.begin(), rim.nodes.end());
            description.node_sets.push_back(std::move(rim));
        }
    }
}

void run_sweep(const PipelineInput& in, const MeshOptions& opt, PipelineResult& out) {
    const auto t0 = Clock::now();
    PhaseProgress progress(opt.progress, "sweep", in.geometry.tubes.size());
    SweepOptions sweep = opt.sweep;
    if (sweep.sweep_size <= 0) sweep.sweep_size = in.geometry.sweep_size;
    sweep.store_boundary_faces = true;
    if (!in.geometry.tubes.empty()) out.sweep = sweep_tubes(out.mesh, in.geometry.tubes, in.surfaces, sweep);
    const double join_gap = in.ring_joins.empty() ? 0.0
                                                  : join_ring_ends(out.mesh, out.sweep, in.ring_joins,
                                                                   kRingJoinShare * sweep.sweep_size);
    add_rims(out.sweep, in.ring_joins, out.mesh, out.description);
    add_pipe_stations(out.sweep, in.ring_joins, out.mesh, out.description);
    const SweepStats& s = out.sweep.stats;
    PhaseReport r{"sweep", seconds_since(t0), {}};
    r.counts = {{"tubes", double(s.tubes)},
                {"nodes", double(s.nodes)},
                {"hexes", double(s.hexes)},
                {"outer quads", double(s.outer_quads)}};
    if (s.hexes > 0) r.statistics = {{"min J_m", s.min_scaled_jacobian}, {"max cond", s.max_condition}};
    if (!in.ring_joins.empty()) {
        r.counts.emplace_back("rings joined", double(in.ring_joins.size()));
        r.statistics.emplace_back("ring join gap", join_gap);
    }
    progress.finish();
    out.phases.push_back(std::move(r));
}

// The tet step's far size: the option when given, else S.
double tet_far_size(const PipelineInput& in, const MeshOptions& opt) {
    return opt.tets.far_size > 0 ? opt.tets.far_size : in.geometry.size;
}

// Surface passes at most (run_surface).
constexpr int kSurfacePasses = 4;

struct SurfacePass {
    surface::SurfaceMeshStats stats;
    index_t edge_points = 0;
};

// The edge where each stopped ring end meets the wall beyond (TubeData::stops), as a closed
// polyline through the ring's wall nodes at that station, appended to `edges`, and those nodes
// for add_edge_nodes: the face beyond meets the ring node for node.
void append_stop_edges(const DiscreteGeometry& g, const SweepResult& sweep, const HybridMesh& mesh,
                       std::vector<EdgePolyline>& edges, std::vector<surface::FixedEdgeNodes>& fixed) {
    for (std::size_t t = 0; t < g.tubes.size() && t < sweep.rings.size(); ++t) {
        const TubeData& tube = g.tubes[t];
        const TubeRing& ring = sweep.rings[t];
        for (std::size_t e = 0; e < 2; ++e) {
            if (!tube.stops[e]) continue;
            const std::vector<index_t>& loop = e == 0 ? tube.loop1_edges : tube.loop2_edges;
            const std::vector<double>& params = tube.stop_params[e];
            const index_t n = ring.circumferential;
            if (loop.size() != 1 || params.size() != std::size_t{n} + 1)
                throw Error("a ring that stops needs one closed edge where it stops and " + std::to_string(n + 1) +
                            " parameters along it, got " + std::to_string(loop.size()) + " edges and " +
                            std::to_string(params.size()) + " parameters");
            const index_t station = e == 0 ? 0 : ring.stations - 1;
            // The polyline runs along the edge's parameter: the ring's order, or against it.
            const bool forward = params.back() > params.front();
            EdgePolyline line;
            line.edge = loop.front();
            surface::FixedEdgeNodes ids{line.edge, {}};
            for (index_t q = 0; q <= n; ++q) {
                const index_t k = forward ? q % n : (n - q) % n;
                const index_t node = ring.node(station, 0, k);
                ids.ids.push_back(node);
                line.points.push_back(mesh.point(node));
                line.params.push_back(forward ? params[q] : params[n - q]);
            }
            line.first_vertex = line.last_vertex = tube.stop_vertex[e];
            edges.push_back(std::move(line));
            fixed.push_back(std::move(ids));
        }
    }
}

// Every face that is not a tube wall (`walls`: tube_wall_faces), meshed into `mesh` with the
// surface field plus `caps`.
SurfacePass mesh_faces(const PipelineInput& in, const MeshOptions& opt, const SweepResult& sweep,
                       const std::unordered_set<index_t>& walls, std::span<const SizeSource> caps,
                       HybridMesh& mesh) {
    const DiscreteGeometry& g = in.geometry;
    std::vector<index_t> tube_loop_edges;
    for (const TubeData& t : g.tubes) {
        // A stopped end's loop is an edge of the face beyond: that face takes the ring's nodes on it.
        if (!t.stops[0]) tube_loop_edges.insert(tube_loop_edges.end(), t.loop1_edges.begin(), t.loop1_edges.end());
        if (!t.stops[1]) tube_loop_edges.insert(tube_loop_edges.end(), t.loop2_edges.begin(), t.loop2_edges.end());
    }

    SurfaceSizing sizing = surface_sizing(in, sweep.rings, opt, caps);
    std::vector<surface::FixedEdgeNodes> fixed;
    append_stop_edges(g, sweep, mesh, sizing.edges, fixed);
    const std::vector<EdgePolyline>& edges = sizing.edges;
    const SizeField size(sizing.options, std::move(sizing.sources));

    SurfacePass pass;
    const index_t points_before = mesh.point_count();
    const surface::EdgeNodes edge_nodes = surface::add_edge_nodes(edges, mesh, fixed);
    pass.edge_points = mesh.point_count() - points_before;

    std::vector<surface::SurfaceFace> faces;
    for (const PipelineFace& f : in.faces) {
        if (f.tube_wall || walls.count(f.id)) continue;
        const SurfaceMap* map = in.surfaces(f.id);
        if (!map) throw Error("face_" + std::to_string(f.id) + " has no surface map");
        std::vector<surface::HolePolygon> holes;
        for (const TubeRing& ring : sweep.rings)
            for (const RingEnd& end : ring.ends)
                if (end.host == f.id) holes.push_back({end.outer_nodes, end.outer_uv});
        surface::SurfaceFace face;
        face.surface = map;
        face.boundary = surface::face_boundary(*map, edges, edge_nodes, tube_loop_edges, holes, mesh, g.size);
        face.group = mesh.surface_group_id("face_" + std::to_string(f.id));
        faces.push_back(std::move(face));
    }
    pass.stats = surface::mesh_surfaces(faces, size, opt.surface, mesh);
    return pass;
}

// Triangles the surface passes left too large for the tets beside them.
struct TooLargeLeft {
    std::size_t triangles = 0;
    int passes = 0;
};

TooLargeLeft run_surface(const PipelineInput& in, const MeshOptions& opt, PipelineResult& out) {
    const auto t0 = Clock::now();
    const std::unordered_set<index_t> walls = tube_wall_faces(in.geometry);
    index_t face_total = 0;
    for (const PipelineFace& f : in.faces) face_total += !(f.tube_wall || walls.count(f.id));
    PhaseProgress progress(opt.progress, "surface", face_total);

    // Each pass meshes the faces into a copy of the rings-only mesh (cheap to copy). Where a
    // pass leaves triangles too large for the tets beside them, their caps join the field and
    // the faces are meshed again (tet_size_caps.hpp says why). The caps only lower the field,
    // but a capped triangle's successors may sit nearer the pipe, where the tets are smaller
    // still: two passes were enough on every block measured (bench/results/tuning-notes.md),
    // and the last pass is kept whatever it leaves.
    const index_t first_triangle = out.mesh.face_count(FaceKind::Tri);
    const ThinRingShares thin = thin_ring_shares(out.mesh, out.sweep, opt.pyramids.height_factor);
    const TetSizeCaps too_large(out.mesh, out.sweep.outer_quads, tet_far_size(in, opt), opt.tets.gradation,
                                opt.size_growth, thin.tet_size);
    SurfacePass pass;
    int passes = 0;
    std::size_t left = 0;  // triangles still too large after the last pass
    for (int k = 1;; ++k) {
        passes = k;
        HybridMesh trial = out.mesh;
        pass = mesh_faces(in, opt, out.sweep, walls, out.surface_size_caps, trial);
        const std::vector<SizeSource> caps = too_large.caps(trial, first_triangle);
        if (caps.empty() || k == kSurfacePasses) {
            out.mesh = std::move(trial);
            left = caps.size();
            break;
        }
        out.surface_size_caps.insert(out.surface_size_caps.end(), caps.begin(), caps.end());
    }
    const surface::SurfaceMeshStats& s = pass.stats;
    PhaseReport r{"surface", seconds_since(t0), {}};
    r.counts = {{"faces", double(s.faces)},
                {"edge nodes", double(pass.edge_points)},
                {"interior nodes", double(s.interior_nodes)},
                {"triangles", double(s.triangles)},
                {"passes", double(passes)},
                {"size caps", double(out.surface_size_caps.size())},
                {"too large left", double(left)}};
    progress.finish();
    out.phases.push_back(std::move(r));
    return {left, passes};
}

// The tubes whose rings hold these outer quads (ascending fronts in, ascending tubes out).
std::vector<index_t> tubes_of_fronts(const SweepResult& sweep, const std::vector<index_t>& fronts) {
    std::vector<index_t> tubes;
    for (const TubeRing& ring : sweep.rings) {
        const index_t first = ring.first_lateral_quad;
        const index_t end = first + (ring.stations - 1) * ring.circumferential;
        auto at = std::lower_bound(fronts.begin(), fronts.end(), first);
        if (at != fronts.end() && *at < end) tubes.push_back(ring.tube);
        // Stop quads follow all outer quads (run_pyramids).
        const index_t lateral = static_cast<index_t>(sweep.outer_quads.size() / 4);
        const index_t stop = lateral + ring.first_stop_quad;
        const index_t stop_end = stop + (index_t(ring.stopped[0]) + index_t(ring.stopped[1])) * ring.radial_layers *
                                            ring.circumferential;
        at = std::lower_bound(fronts.begin(), fronts.end(), stop);
        if (at != fronts.end() && *at < stop_end) tubes.push_back(ring.tube);
    }
    std::sort(tubes.begin(), tubes.end());
    tubes.erase(std::unique(tubes.begin(), tubes.end()), tubes.end());
    return tubes;
}

void run_pyramids(const PipelineInput& input, const MeshOptions& opt, PipelineResult& out) {
    const auto t0 = Clock::now();
    HybridMesh& mesh = out.mesh;
    PhaseProgress progress(opt.progress, "pyramids", out.sweep.outer_quads.size() / 4);
    // Copies: build_pyramids appends to the mesh while it reads these.
    const std::vector<index_t> boundary = mesh.block(FaceKind::Tri).nodes;
    PyramidInput in;
    in.front_quads = out.sweep.outer_quads;
    in.boundary_triangles = boundary;
    in.obstacle_quads = out.sweep.end_quads;
    ThinRingShares thin = thin_ring_shares(mesh, out.sweep, opt.pyramids.height_factor);
    // Rings that stop inside the solid: their end quads are fronts too, after the outer quads,
    // and no obstacles.
    std::vector<index_t> fronts, obstacles;
    if (!out.sweep.stop_quads.empty()) {
        fronts = out.sweep.outer_quads;
        fronts.insert(fronts.end(), out.sweep.stop_quads.begin(), out.sweep.stop_quads.end());
        for (const TubeRing& ring : out.sweep.rings)
            for (std::size_t e = 0; e < 2; ++e) {
                if (ring.stopped[e]) continue;
                const std::size_t first = 4 * (std::size_t{ring.first_end_quad} + e * ring.radial_layers * ring.circumferential);
                const std::size_t count = 4 * std::size_t{ring.radial_layers} * ring.circumferential;
                obstacles.insert(obstacles.end(), out.sweep.end_quads.begin() + first,
                                 out.sweep.end_quads.begin() + first + count);
            }
        in.front_quads = fronts;
        in.obstacle_quads = obstacles;
        if (!thin.apex.empty()) thin.apex.resize(fronts.size() / 4, 1.0);
    }
    in.front_scale = thin.apex;
    in.region = mesh.region_id("pyramids");
    in.sweep_size = opt.sweep.sweep_size > 0 ? opt.sweep.sweep_size : input.geometry.sweep_size;
    PyramidResult p;
    if (!out.sweep.outer_quads.empty()) {
        try {
            PyramidOptions po = opt.pyramids;
            po.pulse = [&progress] { progress.pulse(); };
            p = build_pyramids(mesh, in, po);
        } catch (const PyramidRoomError& e) {
            throw RetryableFailure(e.what(), RetryableFailure::Cause::PyramidRoom, tubes_of_fronts(out.sweep, e.fronts),
                                   e.finding);
        }
    }
    // The tet region's boundary: free pyramid triangles, then the uncovered surface triangles.
    out.tet_front = p.free_triangles;
    std::vector<char> covered(boundary.size() / 3, 0);
    for (index_t t : p.covered_boundary_triangles) covered[t] = 1;
    for (std::size_t t = 0; t < covered.size(); ++t)
        if (!covered[t]) out.tet_front.insert(out.tet_front.end(), boundary.begin() + 3 * t, boundary.begin() + 3 * t + 3);
    out.pyramid_stats = p.stats;
    const PyramidStats& s = p.stats;
    PhaseReport r{"pyramids", seconds_since(t0), {}};
    index_t try_nodes = 0;
    for (index_t k : s.try_node) try_nodes += k;
    r.counts = {{"pyramids", double(s.pyramids)},
                {"ideal apex", double(s.ideal)},
                {"wide wedge apex", double(s.wide)},
                {"existing apex", double(s.existing + s.existing_relaxed)},
                {"try-node apex", double(try_nodes)},
                {"wedge fronts", double(s.wedge_fronts)},
                {"lowered apex", double(s.lowered)},
                {"drawbacks", double(s.drawback_rounds)},
                {"front triangles", double(out.tet_front.size() / 3)}};
    progress.finish();
    out.phases.push_back(std::move(r));
}

void run_tets(const PipelineInput& in, const MeshOptions& opt, const Parallelism& par, PipelineResult& out) {
    const auto t0 = Clock::now();
    PhaseProgress progress(opt.progress, "tets", 3);  // recovery, refinement + relaxation, optimisation
    tets::TetStepOptions to = opt.tets;
    to.far_size = tet_far_size(in, opt);
    to.part_done = [&progress] { progress.advance(); };
    to.pulse = [&progress] { progress.pulse(); };
    // The refinement is where a run's memory grows most: the cap is checked after each round.
    if (std::isfinite(in.cap.limit))
        to.refine.round_done = [&](index_t tets) { check_refining_tets(out.mesh, double(tets), in.cap); };
    try {
        out.tet_stats = tets::build_tets(out.mesh, out.tet_front, out.mesh.region_id("tets"), par, to);
    } catch (const tets::RecoveryGaveUp& e) {
        throw RetryableFailure(e.what(), RetryableFailure::Cause::Recovery);
    }
    const tets::TetStepStats& s = out.tet_stats;
    PhaseReport r{"tets", seconds_since(t0), {}};
    // Recovered: front edges / triangles the Delaunay tets of the front's points lacked, all
    // restored by flips or Steiner points (recovery throws otherwise).
    r.counts = {{"tets", double(s.tets)},
                {"front triangles", double(s.front_triangles)},
                {"new nodes", double(s.new_points)},
                {"front edges recovered", double(s.recovery.missing_edges)},
                {"front faces recovered", double(s.recovery.missing_faces)},
                {"steiner points kept", double(s.recovery.steiner_kept)},
                {"refinement rounds", double(s.refine.rounds)},
                // ODT relaxation: rounds, moves over all of them, the points whose reinsertion
                // needed a second walk, and the points it could not insert again (removed).
                {"relaxation rounds", double(s.relaxation.iterations)},
                {"relaxation moves", double(s.relaxation.moves)},
                {"relaxation second walks", double(s.relaxation.second_walks)},
                {"relaxation points dropped", double(s.relaxation.dropped)},
                {"flips", double(s.optimise.flips23 + s.optimise.flips32 + s.optimise.flips44 + s.optimise.edge_removals)},
                {"smoothing moves", double(s.optimise.moves)},
                // The worst-tet rescue after the passes: tets lifted, and how many of them by a
                // new point (those are among the new nodes).
                {"worst tets rescued", double(s.optimise.rescued)},
                {"rescue points", double(s.optimise.inserted_points)}};
    r.statistics = {{"recovery s", s.recovery.seconds_total},
                    {"recovery delaunay s", s.recovery.seconds_delaunay},
                    {"recovery edges s", s.recovery.seconds_edges},
                    {"recovery faces s", s.recovery.seconds_faces},
                    {"recovery steiner removal s", s.recovery.seconds_steiner_removal},
                    {"recovery classify s", s.recovery.seconds_classify},
                    {"refinement s", s.refine.seconds},
                    {"relaxation s", s.relaxation.seconds},
                    {"optimisation s", s.optimise.seconds_total},
                    {"optimisation flips s", s.optimise.seconds_flips},
                    {"optimisation smoothing s", s.optimise.seconds_smoothing},
                    {"optimisation rescue s", s.optimise.seconds_rescue},
                    {"optimisation passes", double(s.optimise.passes)},
                    {"min collapse before optimisation", s.optimise.min_collapse_before},
                    {"mean collapse before optimisation", s.optimise.mean_collapse_before}};
    progress.finish();
    out.phases.push_back(std::move(r));
}

TooLargeLeft run_phases(const PipelineInput& input, const MeshOptions& options, const Parallelism& par, Stage until,
                        PipelineResult& out) {
    // After each stage, the counts so far and the estimate of the stages left against the cap.
    const auto reach = [&](Stage s) {
        out.reached = s;
        check_element_cap(out.mesh, s, until, double(out.sweep.outer_quads.size() / 4), input.cap);
    };
    run_sweep(input, options, out);
    reach(Stage::Sweep);
    if (until == Stage::Sweep) return {};
    const TooLargeLeft left = run_surface(input, options, out);
    reach(Stage::Surface);
    if (until == Stage::Surface) return left;
    run_pyramids(input, options, out);
    reach(Stage::Pyramids);
    if (until == Stage::Pyramids) return left;
    run_tets(input, options, par, out);
    reach(Stage::Tets);
    return left;
}

}  // namespace

Parallelism run_parallelism(const MeshOptions& options) {
    return resolve_parallelism(options.threads, options.tet_parts);
}

PipelineResult run_pipeline(const PipelineInput& input, const MeshOptions& options, Stage until) {
    const Parallelism par = run_parallelism(options);
    const auto limit = limit_threads(par);

    PipelineResult out;
    const TooLargeLeft left = run_phases(input, options, par, until, out);
    {
        PhaseProgress quality(options.progress, "quality", 1);
        out.quality = summarize_quality(out.mesh, [&quality] { quality.pulse(); });
        quality.finish();
    }
    // Whether the triangles left too large made flat tets is known once the tets are made.
    const std::string warning =
        too_large_warning(left.triangles, left.passes,
                          out.reached == Stage::Tets ? std::optional<double>(out.quality.tet_collapse.min) : std::nullopt);
    if (!warning.empty()) out.warnings.push_back(warning);
    for (const PhaseReport& p : out.phases) out.seconds += p.seconds;
    if (options.check) check_result(out, options.progress);
    return out;
}

}  // namespace tubemesh
