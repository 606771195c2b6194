#include "geom/assembly/mesh_assembly.hpp"

#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <numeric>
#include <unordered_set>

#include "engine/core/timing.hpp"
#include "engine/pipeline/stage_check.hpp"
#include "engine/core/vec3_ops.hpp"
#include "geom/assembly/assembly_occt.hpp"
#include "geom/assembly/solid_tops.hpp"
#include "geom/describe_groups.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/prepare.hpp"
#include "geom/model/surface_map_occt.hpp"

namespace tubemesh::geom {

namespace {

// The assembly's faces and edges as one Model: what the SurfaceMaps and the group descriptions
// are made from (a shared face as the first solid that has it sees it). Its solid holds every
// solid's shells, for the bounds.
Model whole_model(const Assembly& a) {
    auto impl = std::make_unique<Model::Impl>();
    BRep_Builder builder;
    builder.MakeSolid(impl->solid);
    for (const AssemblySolid& s : a.solids())
        for (TopExp_Explorer it(solid_of(s.model), TopAbs_SHELL); it.More(); it.Next()) builder.Add(impl->solid, it.Current());
    impl->faces = a.impl().faces;
    impl->edges = a.impl().edges;
    impl->report.source = a.report().source;
    impl->report.format = a.report().format;
    impl->report.length_unit = a.report().length_unit;
    impl->report.solids_in_file = static_cast<int>(a.solids().size());
    return Model(std::move(impl));
}

template <class Id>
Id global(const std::vector<int>& ids, Id local) {
    return local == 0 ? Id{0} : static_cast<Id>(ids[static_cast<std::size_t>(local) - 1]);
}

template <class Id>
void to_global(const std::vector<int>& ids, std::vector<Id>& list) {
    for (Id& v : list) v = global(ids, v);
}

TubeData global_tube(TubeData t, const AssemblySolid& s) {
    to_global(s.face_ids, t.wall_faces);
    t.host1 = global(s.face_ids, t.host1);
    t.host2 = global(s.face_ids, t.host2);
    to_global(s.edge_ids, t.loop1_edges);
    to_global(s.edge_ids, t.loop2_edges);
    return t;
}

TubeInfo global_info(TubeInfo t, const AssemblySolid& s) {
    to_global(s.face_ids, t.faces);
    for (auto& loop : t.loops) to_global(s.edge_ids, loop);
    for (int& h : t.hosts) h = global(s.face_ids, h);
    return t;
}

// Each solid's plan at one S: the given one, else the smallest of their defaults.
std::vector<PreparedModel> prepare_solids(const Assembly& a, const MeshOptions& options) {
    // A split wall renumbers a solid's faces, which the glue between the solids names.
    PrepareOptions first = prepare_options(options);
    first.stop_rings = false;
    std::vector<PreparedModel> prepared;
    for (const AssemblySolid& s : a.solids()) prepared.push_back(prepare_model(s.model, first));
    if (options.size > 0) return prepared;
    double size = prepared.front().plan.size;
    for (const PreparedModel& p : prepared) size = std::min(size, p.plan.size);
    PrepareOptions common = first;
    common.sizing.size = size;
    for (std::size_t k = 0; k < prepared.size(); ++k)
        if (prepared[k].plan.size != size) prepared[k] = prepare_model(a.solids()[k].model, common);
    return prepared;
}

// geom's phases summed over the solids (their S and St, and counts of the fewest: the smallest).
std::vector<PhaseReport> summed_phases(const std::vector<PreparedModel>& prepared) {
    std::vector<PhaseReport> out = prepared.front().phases;
    for (std::size_t k = 1; k < prepared.size(); ++k)
        for (std::size_t i = 0; i < out.size() && i < prepared[k].phases.size(); ++i) {
            const PhaseReport& p = prepared[k].phases[i];
            out[i].seconds += p.seconds;
            for (std::size_t c = 0; c < out[i].counts.size() && c < p.counts.size(); ++c) {
                auto& [name, value] = out[i].counts[c];
                value = name.ends_with("(fewest)") ? std::min(value, p.counts[c].second) : value + p.counts[c].second;
            }
            for (std::size_t c = 0; c < out[i].statistics.size() && c < p.statistics.size(); ++c)
                out[i].statistics[c].second = std::min(out[i].statistics[c].second, p.statistics[c].second);
        }
    return out;
}

// The ends of tubes on shared faces, paired by face and end loop: each pair is one pipe running
// from one solid into the next. Tubes are numbered solid by solid, as mesh_assembly lays them.
std::vector<RingJoin> find_ring_joins(const Assembly& a, const std::vector<PreparedModel>& prepared) {
    std::map<int, const SharedFace*> shared;
    for (const SharedFace& f : a.shared_faces()) shared[f.face] = &f;
    struct End {
        index_t tube;
        int end;
        std::size_t solid;
    };
    std::map<std::pair<int, std::vector<int>>, std::vector<End>> ends;
    index_t tube = 0;
    for (std::size_t k = 0; k < prepared.size(); ++k) {
        const AssemblySolid& s = a.solids()[k];
        for (const TubeInfo& t : prepared[k].tubes.tubes) {
            for (int e = 0; e < 2; ++e) {
                const int host = global(s.face_ids, t.hosts[static_cast<std::size_t>(e)]);
                if (!shared.count(host)) continue;
                std::vector<int> loop = t.loops[static_cast<std::size_t>(e)];
                to_global(s.edge_ids, loop);
                std::sort(loop.begin(), loop.end());
                ends[{host, loop}].push_back({tube, e, k});
            }
            ++tube;
        }
    }
    std::vector<RingJoin> joins;
    for (const auto& [key, list] : ends) {
        const SharedFace& f = *shared[key.first];
        if (list.size() != 2 || list[0].solid == list[1].solid) {
            const std::size_t k = list[0].solid;
            throw Error(fmt::format("a pipe of '{}' ends on face_{}, which it shares with '{}', and does not run on "
                                    "into it there: continue the pipe through the joint or end it on an outer face",
                                    a.solids()[k].name, f.face,
                                    a.solids()[k == std::size_t(f.first) ? f.second : f.first].name));
        }
        joins.push_back({list[0].tube, list[1].tube, list[0].end, list[1].end});
    }
    std::sort(joins.begin(), joins.end(), [](const RingJoin& x, const RingJoin& y) {
        return std::pair(x.tube_a, x.end_a) < std::pair(y.tube_a, y.end_a);
    });
    return joins;
}

// Solid k's index for every tube, numbered as find_ring_joins does.
std::vector<std::size_t> solid_of_tubes(const std::vector<PreparedModel>& prepared) {
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < prepared.size(); ++k) out.insert(out.end(), prepared[k].tubes.tubes.size(), k);
    return out;
}

// The two pieces of a pipe are one ring at the joint, so they need one St: the solids a pipe
// links take the smallest St among them and are prepared again at it.
void one_sweep_size_per_pipe(const Assembly& a, const MeshOptions& options, const std::vector<RingJoin>& joins,
                             std::vector<PreparedModel>& prepared) {
    const std::vector<std::size_t> solid = solid_of_tubes(prepared);
    std::vector<std::size_t> head(prepared.size());
    std::iota(head.begin(), head.end(), std::size_t{0});
    const auto find = [&](std::size_t k) {
        while (head[k] != k) k = head[k] = head[head[k]];
        return k;
    };
    for (const RingJoin& j : joins) {
        const std::size_t x = find(solid[j.tube_a]), y = find(solid[j.tube_b]);
        head[std::max(x, y)] = std::min(x, y);
    }
    std::vector<double> least(prepared.size(), 0);
    for (std::size_t k = 0; k < prepared.size(); ++k) {
        const double st = prepared[k].geometry.sweep_size;
        double& l = least[find(k)];
        if (st > 0 && (l == 0 || st < l)) l = st;
    }
    for (std::size_t k = 0; k < prepared.size(); ++k) {
        const double st = least[find(k)];
        if (prepared[k].geometry.tubes.empty() || prepared[k].geometry.sweep_size == st) continue;
        PrepareOptions o = prepare_options(options);
        o.stop_rings = false;
        o.sizing.size = prepared[k].plan.size;
        o.sizing.sweep_size = st;
        prepared[k] = prepare_model(a.solids()[k].model, o);
    }
}

// b's end ring on the joint becomes a's, started at the node nearest b's own node 0 and turning
// b's way: the sweep then places both pieces' cross-sections there from the same points.
void share_joint_rings(std::vector<TubeData>& tubes, const std::vector<RingJoin>& joins) {
    for (const RingJoin& j : joins) {
        const std::vector<Vec3>& ra = j.end_a == 0 ? tubes[j.tube_a].ring1 : tubes[j.tube_a].ring2;
        std::vector<Vec3>& rb = j.end_b == 0 ? tubes[j.tube_b].ring1 : tubes[j.tube_b].ring2;
        const std::size_t n = ra.size();
        if (rb.size() != n || n < 3)
            throw Error(fmt::format("the two pieces of a pipe crossing a joint (tubes {} and {}) have {} and {} nodes "
                                    "around: give them one St",
                                    j.tube_a + 1, j.tube_b + 1, n, rb.size()));
        std::size_t k0 = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (distance2(ra[k], rb[0]) < distance2(ra[k0], rb[0])) k0 = k;
        const bool same_way = distance2(ra[(k0 + 1) % n], rb[1]) <= distance2(ra[(k0 + n - 1) % n], rb[1]);
        std::vector<Vec3> ring(n);
        for (std::size_t k = 0; k < n; ++k) ring[k] = ra[same_way ? (k0 + k) % n : (k0 + n - k) % n];
        rb = std::move(ring);
    }
}

}  // namespace

AssemblyRun mesh_assembly(const Assembly& a, const MeshOptions& options) {
    // Each solid would be rounded on its own diagonal's grid, and the faces they share with it.
    if (options.grid_bits > 0)
        throw Error("--scale-free does not apply to an assembly yet: mesh it without --scale-free");
    const auto limit = limit_threads(run_parallelism(options));
    const std::vector<AssemblySolid>& solids = a.solids();
    std::vector<PreparedModel> prepared = prepare_solids(a, options);
    const std::vector<RingJoin> joins = find_ring_joins(a, prepared);
    if (!joins.empty()) one_sweep_size_per_pipe(a, options, joins, prepared);

    DiscreteGeometry geometry;
    geometry.size = prepared.front().geometry.size;
    TubeSearch tube_search;
    AssemblyInput input{PipelineInput{geometry, {}, {}}, {}};
    MeshOptions run_options = options;
    std::map<index_t, EdgePolyline> edges;
    for (std::size_t k = 0; k < solids.size(); ++k) {
        const AssemblySolid& s = solids[k];
        const PreparedModel& p = prepared[k];
        AssemblySolidInput in{s.name, {}, {}, {}};
        for (const TubeData& t : p.geometry.tubes) {
            in.tubes.push_back(static_cast<index_t>(geometry.tubes.size()));
            geometry.tubes.push_back(global_tube(t, s));
            run_options.sweep.tube_sweep_size.push_back(p.geometry.sweep_size);
            if (p.geometry.sweep_size > 0 && (geometry.sweep_size == 0 || p.geometry.sweep_size < geometry.sweep_size))
                geometry.sweep_size = p.geometry.sweep_size;
        }
        for (const TubeInfo& t : p.tubes.tubes) tube_search.tubes.push_back(global_info(t, s));
        for (EdgePolyline e : p.geometry.edges) {
            e.edge = global(s.edge_ids, e.edge);
            e.first_vertex = global(s.vertex_ids, e.first_vertex);
            e.last_vertex = global(s.vertex_ids, e.last_vertex);
            edges.try_emplace(e.edge, std::move(e));
        }
        in.faces.assign(s.face_ids.begin(), s.face_ids.end());
        // Points in the model's space, as every solid's geometry is.
        input.whole.gap_sizes.insert(input.whole.gap_sizes.end(), p.gap_sizes.begin(), p.gap_sizes.end());
        input.solids.push_back(std::move(in));
    }
    for (auto& [id, e] : edges) geometry.edges.push_back(std::move(e));
    share_joint_rings(geometry.tubes, joins);
    input.whole.ring_joins = joins;

    const Model whole = whole_model(a);
    const std::vector<std::unique_ptr<SurfaceMap>> maps = make_surface_maps(whole);
    for (std::size_t k = 0; k < solids.size(); ++k)
        for (std::size_t i = 0; i < prepared[k].maps.size(); ++i) {
            const int id = solids[k].face_ids[i];
            input.solids[k].reversed.push_back(prepared[k].maps[i]->reversed() != maps[id - 1]->reversed());
        }
    std::unordered_set<index_t> walls;
    for (const TubeData& t : geometry.tubes) walls.insert(t.wall_faces.begin(), t.wall_faces.end());
    for (int id = 1; id <= whole.face_count(); ++id)
        input.whole.faces.push_back({static_cast<index_t>(id), walls.count(static_cast<index_t>(id)) > 0});
    input.whole.surfaces = [&maps](index_t face) -> const SurfaceMap* {
        return face == 0 || face > maps.size() ? nullptr : maps[face - 1].get();
    };

    AssemblyResult meshed = run_assembly(input, run_options);
    AssemblyRun out;
    out.solids = std::move(meshed.solids);
    out.shared_triangles = meshed.shared_triangles;
    out.report = a.report();
    MeshRun& run = out.run;
    run.result = std::move(meshed.result);
    PipelineResult& r = run.result;
    const std::vector<PhaseReport> geom_phases = summed_phases(prepared);
    for (const PhaseReport& p : geom_phases) r.seconds += p.seconds;
    r.phases.insert(r.phases.begin(), geom_phases.begin(), geom_phases.end());
    for (std::size_t k = 0; k < solids.size(); ++k)
        for (const std::string& w : prepared[k].warnings) r.warnings.push_back(solids[k].name + ": " + w);
    if (options.check) check_result(r, options.progress);
    // "pipe_<k>" is the k-th pipe (joined tubes are one): described by its first tube.
    TubeSearch pipes;
    const std::vector<index_t> pipe = pipe_of_tubes(tube_search.tubes.size(), joins);
    for (std::size_t t = 0; t < pipe.size(); ++t)
        if (pipe[t] == pipes.tubes.size()) pipes.tubes.push_back(tube_search.tubes[t]);
    describe_groups(whole, pipes, r.mesh, r.description);
    describe_solid_tops(a, r.mesh, r.description);

    run.source = a.report().source;
    run.format = a.report().format;
    run.size = geometry.size;
    run.sweep_size = geometry.sweep_size;
    run.tubes = geometry.tubes.size();
    // Each solid's pipes by the whole's face ids; a ring by its tube in the whole's order.
    std::size_t first_tube = 0;
    for (std::size_t k = 0; k < solids.size(); ++k) {
        for (RingCoverage c : prepared[k].coverage) {
            for (int& f : c.faces) f = solids[k].face_ids[static_cast<std::size_t>(f) - 1];
            std::sort(c.faces.begin(), c.faces.end());
            if (c.tube > 0) c.tube += static_cast<int>(first_tube);
            run.coverage.push_back(std::move(c));
        }
        first_tube += prepared[k].geometry.tubes.size();
    }
    for (std::size_t k = 0; k < solids.size(); ++k) {
        out.cad_volumes.push_back(solids[k].model.volume());
        run.model_lines.push_back(fmt::format("{}: {} tube{}, St = {:.6g}", solids[k].name,
                                              prepared[k].tubes.tubes.size(),
                                              prepared[k].tubes.tubes.size() == 1 ? "" : "s",
                                              prepared[k].geometry.sweep_size));
    }
    return out;
}

AssemblyRun mesh_assembly_file(const std::string& path, const MeshOptions& options, const AssemblyOptions& assembly) {
    const auto limit = limit_threads(run_parallelism(options));
    const auto t0 = Clock::now();
    PhaseProgress progress(options.progress, "import", 1);
    const Assembly a = import_assembly(path, assembly);
    progress.finish();
    PhaseReport import{"import",
                       seconds_since(t0),
                       {{"solids", double(a.solids().size())},
                        {"faces", double(a.face_count())},
                        {"shared faces", double(a.shared_faces().size())},
                        {"glued faces", double(a.report().glued_faces)}},
                       {{"glue tolerance", a.report().glue_tolerance}}};
    AssemblyRun out = mesh_assembly(a, options);
    out.run.result.seconds += import.seconds;
    out.run.result.phases.insert(out.run.result.phases.begin(), std::move(import));
    return out;
}

}  // namespace tubemesh::geom
