#include "engine/pipeline/assembly_pipeline.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <string>
#include <unordered_map>

#include "engine/check/mesh_check.hpp"
#include "engine/core/parallelism.hpp"
#include "engine/core/timing.hpp"
#include "engine/sizing/thin_rings.hpp"

namespace tubemesh {

namespace {

// One solid's pyramids and tets, in a mesh of its own: its boundary's points first (local id i
// is point global[i] of the whole mesh), then what its steps add.
struct SolidWork {
    std::vector<index_t> global;
    HybridMesh mesh;
    std::vector<index_t> boundary;  // local ids, 3 per triangle, normal out of the solid
    std::vector<index_t> front_quads, obstacle_quads;
    std::vector<double> front_scale;  // per front quad, its apex share over a thin ring (thin_rings.hpp)
    std::vector<index_t> tet_front;
    PyramidStats pyramid_stats;
    tets::TetStepStats tet_stats;
    double pyramid_seconds = 0, tet_seconds = 0;
};

// The B-rep face behind every surface group "face_<id>"; 0 for the others.
std::vector<index_t> face_of_groups(const HybridMesh& mesh) {
    std::vector<index_t> out(mesh.surface_group_names.size(), 0);
    for (std::size_t g = 0; g < out.size(); ++g) {
        const std::string& name = mesh.surface_group_names[g];
        if (name.rfind("face_", 0) == 0) out[g] = static_cast<index_t>(std::stoul(name.substr(5)));
    }
    return out;
}

// The B-rep face of every boundary triangle of the whole mesh.
std::vector<index_t> triangle_faces(const HybridMesh& mesh) {
    const std::vector<index_t> face_of_group = face_of_groups(mesh);
    const FaceBlock& tris = mesh.block(FaceKind::Tri);
    std::vector<index_t> out(tris.group.size());
    for (std::size_t t = 0; t < out.size(); ++t) out[t] = face_of_group[tris.group[t]];
    return out;
}

void append_range(const std::vector<index_t>& from, index_t first, index_t count, std::vector<index_t>& to) {
    to.insert(to.end(), from.begin() + 4 * first, from.begin() + 4 * (first + count));
}

// The solid's boundary triangles and ring quads, renumbered into a mesh of its own.
SolidWork gather_solid(const PipelineResult& whole, const std::vector<index_t>& tri_face,
                       const AssemblySolidInput& solid, const std::vector<double>& apex) {
    std::unordered_map<index_t, char> flip;
    for (std::size_t i = 0; i < solid.faces.size(); ++i) flip[solid.faces[i]] = solid.reversed[i];
    SolidWork w;
    const FaceBlock& tris = whole.mesh.block(FaceKind::Tri);
    for (std::size_t t = 0; t < tri_face.size(); ++t) {
        const auto it = flip.find(tri_face[t]);
        if (it == flip.end()) continue;
        const index_t* n = &tris.nodes[3 * t];
        if (it->second) w.boundary.insert(w.boundary.end(), {n[0], n[2], n[1]});
        else w.boundary.insert(w.boundary.end(), {n[0], n[1], n[2]});
    }
    for (index_t k : solid.tubes) {
        const TubeRing& ring = whole.sweep.rings[k];
        append_range(whole.sweep.outer_quads, ring.first_lateral_quad, (ring.stations - 1) * ring.circumferential,
                     w.front_quads);
        if (!apex.empty())
            w.front_scale.insert(w.front_scale.end(), apex.begin() + ring.first_lateral_quad,
                                 apex.begin() + ring.first_lateral_quad + (ring.stations - 1) * ring.circumferential);
        append_range(whole.sweep.end_quads, ring.first_end_quad, 2 * ring.radial_layers * ring.circumferential,
                     w.obstacle_quads);
    }
    w.global = w.boundary;
    w.global.insert(w.global.end(), w.front_quads.begin(), w.front_quads.end());
    w.global.insert(w.global.end(), w.obstacle_quads.begin(), w.obstacle_quads.end());
    std::sort(w.global.begin(), w.global.end());
    w.global.erase(std::unique(w.global.begin(), w.global.end()), w.global.end());
    const auto local = [&](index_t g) {
        return static_cast<index_t>(std::lower_bound(w.global.begin(), w.global.end(), g) - w.global.begin());
    };
    for (auto* list : {&w.boundary, &w.front_quads, &w.obstacle_quads})
        for (index_t& v : *list) v = local(v);
    for (index_t g : w.global) w.mesh.add_point(whole.mesh.x[g], whole.mesh.y[g], whole.mesh.z[g]);
    w.mesh.region_id(solid.name);
    return w;
}

void run_solid_pyramids(SolidWork& w, const MeshOptions& opt) {
    const auto t0 = Clock::now();
    PyramidResult p;
    if (!w.front_quads.empty()) {
        PyramidInput in;
        in.front_quads = w.front_quads;
        in.boundary_triangles = w.boundary;
        in.obstacle_quads = w.obstacle_quads;
        in.front_scale = w.front_scale;
        in.region = 0;
        p = build_pyramids(w.mesh, in, opt.pyramids);
    }
    w.tet_front = p.free_triangles;
    std::vector<char> covered(w.boundary.size() / 3, 0);
    for (index_t t : p.covered_boundary_triangles) covered[t] = 1;
    for (std::size_t t = 0; t < covered.size(); ++t)
        if (!covered[t]) w.tet_front.insert(w.tet_front.end(), w.boundary.begin() + 3 * t, w.boundary.begin() + 3 * t + 3);
    w.pyramid_stats = p.stats;
    w.pyramid_seconds = seconds_since(t0);
}

void run_solid_tets(SolidWork& w, const MeshOptions& opt, const Parallelism& par, double far_size) {
    const auto t0 = Clock::now();
    tets::TetStepOptions to = opt.tets;
    to.far_size = far_size;
    w.tet_stats = tets::build_tets(w.mesh, w.tet_front, 0, par, to);
    w.tet_seconds = seconds_since(t0);
}

// Runs `step` on every solid side by side, the largest (by its boundary and ring) first: each
// thread takes the next solid in that order when it is free, so a large solid does not start
// last. The solids do not share data, so the order changes no result. An error names the solid.
template <class Step>
void for_each_solid(std::vector<SolidWork>& work, const AssemblyInput& in, PhaseProgress& progress, Step step) {
    std::vector<std::size_t> order(work.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto size = [&](std::size_t k) { return work[k].boundary.size() + 3 * work[k].front_quads.size(); };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return size(a) > size(b); });
    std::vector<std::string> errors(work.size());
    std::atomic<std::size_t> next{0};
    const int workers = std::min<int>(tbb::this_task_arena::max_concurrency(), static_cast<int>(work.size()));
    tbb::parallel_for(0, workers, [&](int) {
        for (std::size_t i; (i = next.fetch_add(1)) < order.size();) {
            const std::size_t k = order[i];
            try {
                step(work[k]);
            } catch (const Error& e) {
                errors[k] = e.what();
            }
            progress.advance();
        }
    });
    for (std::size_t k = 0; k < work.size(); ++k)
        if (!errors[k].empty()) throw Error(in.solids[k].name + ": " + errors[k]);
}

// The solids' cells into the whole mesh, in solid order: region k is solid k.
void merge_solids(std::vector<SolidWork>& work, HybridMesh& mesh) {
    for (std::size_t k = 0; k < work.size(); ++k) {
        SolidWork& w = work[k];
        std::vector<index_t> to_global = w.global;
        for (index_t i = static_cast<index_t>(w.global.size()); i < w.mesh.point_count(); ++i)
            to_global.push_back(mesh.add_point(w.mesh.x[i], w.mesh.y[i], w.mesh.z[i]));
        for (CellKind kind : {CellKind::Pyramid, CellKind::Tet}) {
            const CellBlock& from = w.mesh.block(kind);
            CellBlock& to = mesh.block(kind);
            for (index_t v : from.nodes) to.nodes.push_back(to_global[v]);
            to.region.insert(to.region.end(), from.region.size(), static_cast<index_t>(k));
        }
        w.mesh.clear();
    }
}

// The cells of one region and their points alone: for per-solid measures.
HybridMesh region_mesh(const HybridMesh& mesh, index_t region) {
    HybridMesh out;
    out.region_names = {mesh.region_names[region]};
    std::vector<index_t> local(mesh.point_count(), kNoIndex);
    std::vector<index_t> nodes;
    for (int k = 0; k < kCellKindCount; ++k) {
        const CellKind kind = static_cast<CellKind>(k);
        for (index_t c = 0; c < mesh.cell_count(kind); ++c) {
            if (mesh.block(kind).region[c] != region) continue;
            nodes.clear();
            for (index_t v : mesh.cell(kind, c)) {
                if (local[v] == kNoIndex) local[v] = out.add_point(mesh.x[v], mesh.y[v], mesh.z[v]);
                nodes.push_back(local[v]);
            }
            out.add_cell(kind, nodes, 0);
        }
    }
    return out;
}

// A shared face's triangles and ring end quads are interior faces now: they go to the interface
// group "joint_<A>_<B>" of its two solids. Returns the triangles moved.
index_t group_shared_faces(const AssemblyInput& in, HybridMesh& mesh) {
    std::unordered_map<index_t, std::vector<index_t>> solids_of_face;
    for (std::size_t k = 0; k < in.solids.size(); ++k)
        for (index_t f : in.solids[k].faces) solids_of_face[f].push_back(static_cast<index_t>(k));
    const std::vector<index_t> face_of_group = face_of_groups(mesh);
    std::vector<index_t> to(face_of_group.size());
    for (std::size_t g = 0; g < to.size(); ++g) {
        to[g] = static_cast<index_t>(g);
        const auto it = solids_of_face.find(face_of_group[g]);
        if (face_of_group[g] == 0 || it == solids_of_face.end() || it->second.size() < 2) continue;
        to[g] = mesh.surface_group_id("joint_" + in.solids[it->second[0]].name + "_" + in.solids[it->second[1]].name);
    }
    index_t moved = 0;
    for (int k = 0; k < kFaceKindCount; ++k)
        for (index_t& g : mesh.faces[k].group)
            if (to[g] != g) {
                g = to[g];
                moved += k == static_cast<int>(FaceKind::Tri);
            }
    return moved;
}

// Points no cell uses (the second cross-section of two joined rings) leave; the others keep
// their order.
void drop_unused_points(HybridMesh& mesh, MeshDescription& description) {
    std::vector<char> used(mesh.point_count(), 0);
    for (const CellBlock& b : mesh.cells)
        for (index_t v : b.nodes) used[v] = 1;
    std::vector<index_t> to(used.size(), kNoIndex);
    index_t next = 0;
    for (std::size_t p = 0; p < used.size(); ++p) {
        if (!used[p]) continue;
        mesh.x[next] = mesh.x[p];
        mesh.y[next] = mesh.y[p];
        mesh.z[next] = mesh.z[p];
        to[p] = next++;
    }
    if (next == used.size()) return;
    mesh.x.resize(next);
    mesh.y.resize(next);
    mesh.z.resize(next);
    for (CellBlock& b : mesh.cells)
        for (index_t& v : b.nodes) v = to[v];
    for (FaceBlock& b : mesh.faces)
        for (index_t& v : b.nodes) v = to[v];
    for (NamedNodeSet& set : description.node_sets) {
        std::vector<index_t> kept;
        for (index_t v : set.nodes)
            if (to[v] != kNoIndex) kept.push_back(to[v]);
        set.nodes = std::move(kept);
    }
    for (PipeStations& pipe : description.pipes)
        for (index_t& v : pipe.wall_nodes) v = to[v];
}

// Surface groups left without faces (the shared faces') go; the others keep their order.
void drop_empty_groups(HybridMesh& mesh) {
    std::vector<index_t> used(mesh.surface_group_names.size(), 0);
    for (const FaceBlock& b : mesh.faces)
        for (index_t g : b.group) used[g] = 1;
    std::vector<index_t> new_id(used.size(), kNoIndex);
    std::vector<std::string> names;
    for (std::size_t g = 0; g < used.size(); ++g)
        if (used[g]) {
            new_id[g] = static_cast<index_t>(names.size());
            names.push_back(mesh.surface_group_names[g]);
        }
    for (FaceBlock& b : mesh.faces)
        for (index_t& g : b.group) g = new_id[g];
    mesh.surface_group_names = std::move(names);
}

}  // namespace

AssemblyResult run_assembly(const AssemblyInput& input, const MeshOptions& options) {
    const Parallelism par = run_parallelism(options);
    const auto limit = limit_threads(par);
    AssemblyResult out;
    PipelineResult& r = out.result;
    r = run_pipeline(input.whole, options, Stage::Surface);
    r.seconds = 0;

    const std::vector<index_t> tri_face = triangle_faces(r.mesh);
    std::vector<SolidWork> work;
    const ThinRingShares thin = thin_ring_shares(r.mesh, r.sweep, options.pyramids.height_factor);
    for (const AssemblySolidInput& s : input.solids) work.push_back(gather_solid(r, tri_face, s, thin.apex));
    const double far_size = options.tets.far_size > 0 ? options.tets.far_size : input.whole.geometry.size;

    auto t0 = Clock::now();
    {
        PhaseProgress progress(options.progress, "pyramids", work.size());
        for_each_solid(work, input, progress, [&](SolidWork& w) { run_solid_pyramids(w, options); });
        progress.finish();
    }
    PhaseReport pyramids{"pyramids", seconds_since(t0), {}, {}};
    t0 = Clock::now();
    {
        PhaseProgress progress(options.progress, "tets", work.size());
        for_each_solid(work, input, progress, [&](SolidWork& w) { run_solid_tets(w, options, par, far_size); });
        progress.finish();
    }
    PhaseReport tets{"tets", seconds_since(t0), {}, {}};

    double apexes = 0, front = 0, new_nodes = 0, recovered = 0, steiner = 0;
    for (std::size_t k = 0; k < work.size(); ++k) {
        const SolidWork& w = work[k];
        SolidSummary s;
        s.name = input.solids[k].name;
        s.pyramids = w.pyramid_stats.pyramids;
        s.tets = w.tet_stats.tets;
        s.pyramid_seconds = w.pyramid_seconds;
        s.tet_seconds = w.tet_seconds;
        s.tet_stats = w.tet_stats;
        out.solids.push_back(std::move(s));
        apexes += w.pyramid_stats.ideal + w.pyramid_stats.wide;
        front += w.tet_stats.front_triangles;
        new_nodes += w.tet_stats.new_points;
        recovered += w.tet_stats.recovery.missing_edges + w.tet_stats.recovery.missing_faces;
        steiner += w.tet_stats.recovery.steiner_kept;
    }
    merge_solids(work, r.mesh);

    // Regions: solid k, hexes by the solid their tube lies in.
    r.mesh.region_names.clear();
    for (const AssemblySolidInput& s : input.solids) r.mesh.region_names.push_back(s.name);
    CellBlock& hexes = r.mesh.block(CellKind::Hex);
    for (std::size_t k = 0; k < input.solids.size(); ++k)
        for (index_t t : input.solids[k].tubes) {
            const TubeRing& ring = r.sweep.rings[t];
            std::fill_n(hexes.region.begin() + ring.first_hex, ring.hex_count, static_cast<index_t>(k));
        }
    out.shared_triangles = group_shared_faces(input, r.mesh);
    drop_empty_groups(r.mesh);
    drop_unused_points(r.mesh, r.description);

    index_t pyramid_total = 0, tet_total = 0;
    for (SolidSummary& s : out.solids) {
        pyramid_total += s.pyramids;
        tet_total += s.tets;
    }
    pyramids.counts = {{"solids", double(work.size())}, {"pyramids", double(pyramid_total)}, {"ideal apex", apexes}};
    tets.counts = {{"tets", double(tet_total)},
                   {"front triangles", front},
                   {"new nodes", new_nodes},
                   {"front edges and faces recovered", recovered},
                   {"steiner points kept", steiner},
                   {"shared triangles", double(out.shared_triangles)}};
    r.phases.push_back(std::move(pyramids));
    r.phases.push_back(std::move(tets));
    r.reached = Stage::Tets;

    tbb::parallel_for(std::size_t{0}, out.solids.size(), [&](std::size_t k) {
        const HybridMesh part = region_mesh(r.mesh, static_cast<index_t>(k));
        SolidSummary& s = out.solids[k];
        s.hexes = part.cell_count(CellKind::Hex);
        s.nodes = part.point_count();
        s.quality = summarize_quality(part);
        s.volume = check_mesh(part).volume;
    });
    r.quality = summarize_quality(r.mesh);
    for (const PhaseReport& p : r.phases) r.seconds += p.seconds;
    return out;
}

}  // namespace tubemesh
