#include "engine/core/timing.hpp"
#include "tests/support/pipeline_acceptance_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <sstream>
#include <utility>

#include "engine/core/vec3_ops.hpp"
#include "engine/pipeline/surface_sizing.hpp"
#include "engine/quality/quality.hpp"
#include "engine/sizing/field/size_field.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/model/face_properties.hpp"
#include "tests/support/sweep_checks.hpp"

namespace tubemesh::acceptance {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDegree = 180 / std::numbers::pi;

// "face_12" -> 12; 0 for any other group name.
index_t face_of_group(const std::string& name) {
    if (name.rfind("face_", 0) != 0) return 0;
    return static_cast<index_t>(std::stoul(name.substr(5)));
}

index_t find_root(std::vector<index_t>& parent, index_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// Connected pieces of the mesh's boundary faces, joined through shared nodes.
index_t count_components(const HybridMesh& mesh) {
    std::vector<index_t> parent(mesh.point_count());
    std::iota(parent.begin(), parent.end(), index_t{0});
    std::vector<char> used(mesh.point_count(), 0);
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
        for (index_t f = 0; f < mesh.face_count(k); ++f) {
            const auto nodes = mesh.face(k, f);
            for (index_t v : nodes) used[v] = 1;
            for (std::size_t i = 1; i < nodes.size(); ++i)
                parent[find_root(parent, nodes[i])] = find_root(parent, nodes[0]);
        }
    index_t roots = 0;
    for (index_t v = 0; v < mesh.point_count(); ++v) roots += used[v] && find_root(parent, v) == v;
    return roots;
}

SurfaceFigures inspect_surface(const HybridMesh& mesh, index_t tubes) {
    SurfaceFigures s;
    s.closed = testing::inspect_closed(mesh);
    s.components = count_components(mesh);
    s.tubes = tubes;
    return s;
}

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * norm(cross(b - a, c - a)); }

double mean_edge(const Vec3& a, const Vec3& b, const Vec3& c) { return (norm(b - a) + norm(c - b) + norm(a - c)) / 3; }

// Angle at a between ab and ac, in degrees.
double corner_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 u = b - a, v = c - a;
    return std::atan2(norm(cross(u, v)), dot(u, v)) * kDegree;
}

void measure_rings(const geom::PreparedModel& prepared, const PipelineResult& r, RingAcceptance& out) {
    const QualitySummary q = summarize_quality(r.mesh);
    out.hexes = q.hex_scaled_jacobian.count;
    out.min_jacobian = q.hex_scaled_jacobian.min;
    out.mean_jacobian = q.hex_scaled_jacobian.mean;
    out.max_condition = q.hex_condition.max;

    const PipelineInput input = prepared.pipeline_input();
    for (const TubeRing& ring : r.sweep.rings) {
        const TubeData& tube = prepared.geometry.tubes[ring.tube];
        double radius = 0;
        for (const TubeStation& s : tube.stations) radius += s.radius;
        radius /= static_cast<double>(tube.stations.size());
        // Wall nodes, station after station: the previous station's foot point is the hint, so
        // the search stays local on a long B-spline wall.
        std::vector<std::optional<Uv>> hint(tube.wall_faces.size() * ring.circumferential);
        for (index_t i = 0; i < ring.stations; ++i)
            for (index_t k = 0; k < ring.circumferential; ++k) {
                const Vec3 p = r.mesh.point(ring.node(i, 0, k));
                double d = kInf;
                for (std::size_t w = 0; w < tube.wall_faces.size(); ++w) {
                    const Projection pr = input.surfaces(tube.wall_faces[w])->project(p, hint[w * ring.circumferential + k]);
                    if (!pr.ok) continue;
                    hint[w * ring.circumferential + k] = pr.uv;
                    d = std::min(d, pr.distance);
                }
                out.wall_error = std::max(out.wall_error, d / radius);
                if (i > 0 && i + 1 < ring.stations)
                    out.wall_error_inner_stations = std::max(out.wall_error_inner_stations, d / radius);
            }
        for (const RingEnd& end : ring.ends) {
            const SurfaceMap* host = input.surfaces(end.host);
            for (index_t j = 0; j <= ring.radial_layers; ++j)
                for (index_t k = 0; k < ring.circumferential; ++k) {
                    const Projection pr = host->project(r.mesh.point(ring.node(end.station, j, k)), std::nullopt);
                    out.host_error = std::max(out.host_error, pr.ok ? pr.distance / radius : kInf);
                }
        }
    }
}

void measure_face_areas(const geom::Model& model, const PipelineInput& input, const HybridMesh& mesh,
                        SurfaceAcceptance& out) {
    // Per face: mesh area, and the chord bound sum A_t (1/cos a_t - 1), a_t the largest angle
    // between the element's plane and the surface normal at its corners — the area a patch of
    // the surface has over a flat element that deviates from it by at most a_t.
    std::map<index_t, std::pair<double, double>> faces;  // face -> (area, chord bound)
    for (FaceKind kind : {FaceKind::Tri, FaceKind::Quad}) {
        const FaceBlock& b = mesh.block(kind);
        const std::size_t nv = kind == FaceKind::Tri ? 3 : 4;
        for (std::size_t f = 0; f < b.group.size(); ++f) {
            const index_t face = face_of_group(mesh.surface_group_names[b.group[f]]);
            if (face == 0) continue;  // a tube wall
            const SurfaceMap* map = input.surfaces(face);
            for (std::size_t t = 0; t + 2 < nv; ++t) {  // quads as (0 1 2) and (0 2 3)
                const index_t ids[3] = {b.nodes[nv * f], b.nodes[nv * f + t + 1], b.nodes[nv * f + t + 2]};
                const Vec3 a = mesh.point(ids[0]), c1 = mesh.point(ids[1]), c2 = mesh.point(ids[2]);
                const double area = triangle_area(a, c1, c2);
                double cos_min = 1;
                if (area > 0) {
                    const Vec3 n = (1 / (2 * area)) * cross(c1 - a, c2 - a);
                    for (const Vec3& p : {a, c1, c2}) {
                        const Projection pr = map->project(p, std::nullopt);
                        if (pr.ok) cos_min = std::min(cos_min, std::abs(dot(n, map->normal(pr.uv))));
                    }
                }
                auto& acc = faces[face];
                acc.first += area;
                acc.second += cos_min > 0 ? area * (1 / cos_min - 1) : kInf;
            }
        }
    }
    std::ostringstream problems;
    for (const auto& [face, acc] : faces) {
        const geom::FaceProperties brep = geom::face_properties(model, static_cast<int>(face));
        const double rel = std::abs(acc.first - brep.area) / brep.area;
        if (brep.planar) {
            out.flat_area_error = std::max(out.flat_area_error, rel);
            if (rel > 1e-3) problems << "  flat face_" << face << ": mesh " << acc.first << ", B-rep " << brep.area << "\n";
        } else {
            ++out.curved_faces;
            out.curved_area_error = std::max(out.curved_area_error, rel);
            const double bound = acc.second + 1e-3 * brep.area;
            if (std::abs(acc.first - brep.area) > bound) {
                ++out.curved_over_chord;
                problems << "  curved face_" << face << ": mesh " << acc.first << ", B-rep " << brep.area
                         << ", chord bound " << bound << "\n";
            }
        }
    }
    out.area_problems = problems.str();
}

void measure_surface(const geom::BuiltBlock& block, const geom::PreparedModel& prepared, const PipelineResult& r,
                     const MeshOptions& options, SurfaceAcceptance& out) {
    const HybridMesh& mesh = r.mesh;
    const PipelineInput input = prepared.pipeline_input();
    const FaceBlock& tris = mesh.block(FaceKind::Tri);
    out.triangles = static_cast<index_t>(tris.group.size());
    out.surface = inspect_surface(mesh, static_cast<index_t>(prepared.geometry.tubes.size()));

    // Nodes on their faces, each (node, face) once.
    SurfaceSizing sizing = surface_sizing(input, r.sweep.rings, options, r.surface_size_caps);  // the field the mesher had
    const SizeField size(sizing.options, std::move(sizing.sources));
    std::map<std::pair<index_t, index_t>, char> seen;
    for (std::size_t t = 0; t < tris.group.size(); ++t) {
        const index_t face = face_of_group(mesh.surface_group_names[tris.group[t]]);
        const SurfaceMap* map = input.surfaces(face);
        for (int v = 0; v < 3; ++v) {
            const index_t node = tris.nodes[3 * t + v];
            if (!seen.emplace(std::make_pair(node, face), 1).second) continue;
            const Vec3 p = mesh.point(node);
            const Projection pr = map->project(p, std::nullopt);
            out.node_error = std::max(out.node_error, pr.ok ? pr.distance / size.at(p) : kInf);
        }
    }

    // Angles, and neighbours across every edge two triangles share.
    out.min_angle = 180;
    index_t good = 0;
    std::map<std::pair<index_t, index_t>, std::vector<index_t>> edges;
    std::vector<double> sizes(tris.group.size());
    for (std::size_t t = 0; t < tris.group.size(); ++t) {
        const index_t* n = &tris.nodes[3 * t];
        const Vec3 a = mesh.point(n[0]), b = mesh.point(n[1]), c = mesh.point(n[2]);
        const double angles[3] = {corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)};
        const double smallest = std::min({angles[0], angles[1], angles[2]});
        out.min_angle = std::min(out.min_angle, smallest);
        good += smallest >= 40;
        sizes[t] = mean_edge(a, b, c);
        for (int e = 0; e < 3; ++e)
            edges[{std::min(n[e], n[(e + 1) % 3]), std::max(n[e], n[(e + 1) % 3])}].push_back(static_cast<index_t>(t));
    }
    out.fraction_above_40 = tris.group.empty() ? 1 : double(good) / double(tris.group.size());
    for (const auto& [e, ts] : edges) {
        if (ts.size() != 2) continue;
        const double ratio = std::max(sizes[ts[0]], sizes[ts[1]]) / std::min(sizes[ts[0]], sizes[ts[1]]);
        ++out.pairs;
        out.pairs_above_1_5 += ratio > 1.5;
        if (ratio > out.max_neighbor_ratio) {
            out.max_neighbor_ratio = ratio;
            const Vec3 p = mesh.point(e.first);
            std::ostringstream w;
            w << mesh.surface_group_names[tris.group[ts[0]]] << "/" << mesh.surface_group_names[tris.group[ts[1]]]
              << " near (" << p.x << ", " << p.y << ", " << p.z << "), sizes " << sizes[ts[0]] << " and "
              << sizes[ts[1]] << ", h(x) " << size.at(p);
            out.worst_pair = w.str();
        }
    }
    measure_face_areas(block.model, input, mesh, out);
}

void measure_pyramids(const PipelineResult& r, index_t tubes, PyramidAcceptance& out) {
    const HybridMesh& mesh = r.mesh;
    out.outer_quads = static_cast<index_t>(r.sweep.outer_quads.size() / 4);
    out.pyramids = mesh.cell_count(CellKind::Pyramid);
    std::map<std::array<index_t, 4>, index_t> bases;
    auto key = [](const index_t* q) {
        std::array<index_t, 4> k{q[0], q[1], q[2], q[3]};
        std::sort(k.begin(), k.end());
        return k;
    };
    const CellBlock& pyr = mesh.block(CellKind::Pyramid);
    for (std::size_t p = 0; p < pyr.region.size(); ++p) ++bases[key(&pyr.nodes[5 * p])];
    for (std::size_t q = 0; q < out.outer_quads; ++q) {
        const auto it = bases.find(key(&r.sweep.outer_quads[4 * q]));
        out.quads_without_one_pyramid += it == bases.end() || it->second != 1;
    }

    HybridMesh front;
    front.x = mesh.x;
    front.y = mesh.y;
    front.z = mesh.z;
    const index_t group = front.surface_group_id("tet_front");
    for (std::size_t t = 0; t < r.tet_front.size(); t += 3)
        front.add_face(FaceKind::Tri, std::span<const index_t>(r.tet_front.data() + t, 3), group);
    out.front = inspect_surface(front, tubes);

    const QualitySummary q = summarize_quality(mesh);
    out.min_jacobian = q.pyramid_jacobian.min;
    out.mean_jacobian = q.pyramid_jacobian.mean;
    out.stats = r.pyramid_stats;
}

void expect_closed(const std::string& what, const SurfaceFigures& s) {
    SCOPED_TRACE(what);
    EXPECT_GT(s.closed.faces, 0u);
    EXPECT_EQ(s.closed.open_edges, 0u) << "not watertight";
    EXPECT_EQ(s.closed.nonmanifold_edges, 0u);
    EXPECT_EQ(s.closed.nonmanifold_vertices, 0u);
    EXPECT_EQ(s.closed.misoriented_edges, 0u) << "not consistently oriented";
    EXPECT_EQ(s.closed.crossing_pairs, 0u) << "self-intersecting";
    EXPECT_EQ(s.closed.touching_pairs, 0u) << "faces without a common node touch";
    EXPECT_EQ(s.components, 1u) << "not one surface";
    EXPECT_EQ(s.closed.euler, 2 - 2 * long(s.tubes)) << "not a sphere with one handle per tube";
    EXPECT_GT(s.closed.volume, 0) << "normals point inwards";
}

std::string closed_line(const SurfaceFigures& s) {
    std::ostringstream o;
    o << s.closed.faces << " faces, open " << s.closed.open_edges << ", non-manifold " << s.closed.nonmanifold_edges
      << "/" << s.closed.nonmanifold_vertices << ", misoriented " << s.closed.misoriented_edges << ", crossing "
      << s.closed.crossing_pairs << ", touching " << s.closed.touching_pairs << ", pieces " << s.components
      << ", Euler " << s.closed.euler << ", volume " << s.closed.volume;
    return o.str();
}

}  // namespace

CaseFigures measure_case(const std::string& name, const geom::BlockSpec& spec, const geom::PrepareOptions& options,
                         const MeshOptions& mesh_options) {
    CaseFigures f;
    f.name = name;
    const geom::BuiltBlock block = geom::build_block(spec);
    const geom::PreparedModel prepared = geom::prepare_model(block.model, options);
    const PipelineInput input = prepared.pipeline_input();
    f.tubes = static_cast<index_t>(prepared.geometry.tubes.size());
    f.size = prepared.geometry.size;
    f.sweep_size = prepared.geometry.sweep_size;
    {
        const PipelineResult sweep = run_pipeline(input, mesh_options, Stage::Sweep);
        f.rings.ring_check = check_mesh(sweep_testing::with_outer_quads(sweep.mesh, sweep.sweep));
    }
    const auto t0 = Clock::now();
    const PipelineResult r = run_pipeline(input, mesh_options, Stage::Pyramids);
    f.seconds = seconds_since(t0);
    measure_rings(prepared, r, f.rings);
    measure_surface(block, prepared, r, mesh_options, f.surface);
    measure_pyramids(r, f.tubes, f.pyramids);
    return f;
}

std::string summary(const CaseFigures& f) {
    std::ostringstream o;
    const RingAcceptance& h = f.rings;
    const SurfaceAcceptance& s = f.surface;
    const PyramidAcceptance& p = f.pyramids;
    o << f.name << ": " << f.tubes << " tubes, S " << f.size << ", St " << f.sweep_size << ", pipeline " << f.seconds
      << " s\n";
    o << "  hex: " << h.hexes << ", J_m min " << h.min_jacobian << " mean " << h.mean_jacobian << ", Cond max "
      << h.max_condition << ", wall " << h.wall_error << " r (inner stations " << h.wall_error_inner_stations
      << " r), host " << h.host_error << " r, ring check "
      << (h.ring_check.ok() ? "ok" : "FAILED") << "\n";
    o << "  surface: " << s.triangles << " triangles, " << closed_line(s.surface) << "\n";
    o << "    node off face " << s.node_error << " h, min angle " << s.min_angle << ", all >= 40: "
      << 100 * s.fraction_above_40 << " %, flat area " << s.flat_area_error << ", curved area "
      << s.curved_area_error << " (" << s.curved_over_chord << "/" << s.curved_faces << " over chord bound)\n";
    o << "    neighbour ratio max " << s.max_neighbor_ratio << " (" << s.pairs_above_1_5 << " of " << s.pairs
      << " pairs > 1.5" << (s.worst_pair.empty() ? "" : ", worst " + s.worst_pair) << ")\n";
    o << "  pyramids: " << p.pyramids << " on " << p.outer_quads << " outer quads, " << p.quads_without_one_pyramid
      << " without exactly one; Jacobian min " << p.min_jacobian << " mean " << p.mean_jacobian << "\n";
    index_t tries = 0;
    for (index_t k : p.stats.try_node) tries += k;
    o << "    ideal " << p.stats.ideal << ", existing " << p.stats.existing << ", existing relaxed "
      << p.stats.existing_relaxed << ", try nodes " << tries << ", rejected " << p.stats.rejected << "/"
      << p.stats.rejected_relaxed << ", drawbacks " << p.stats.drawback_rounds << ", batches " << p.stats.batches
      << "\n";
    o << "    front: " << closed_line(p.front) << "\n";
    return o.str();
}

void expect_rings_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " hex rings");
    const RingAcceptance& h = f.rings;
    EXPECT_GT(h.hexes, 0u);
    EXPECT_GE(h.min_jacobian, 0.5);
    EXPECT_LE(h.max_condition, 4.0);
    EXPECT_GE(h.mean_jacobian, 0.70);
    EXPECT_LE(h.host_error, 1e-7);
    EXPECT_TRUE(h.ring_check.ok()) << describe(h.ring_check);
}

void expect_surface_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " surface");
    const SurfaceAcceptance& s = f.surface;
    EXPECT_GT(s.triangles, 0u);
    expect_closed("end quads + triangles + wall quads", s.surface);
    EXPECT_LE(s.node_error, 1e-7);
    EXPECT_EQ(s.curved_over_chord, 0u) << s.area_problems;
}

void expect_wall_nodes_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " wall nodes");
    EXPECT_LE(f.rings.wall_error, 1e-7);
}

void expect_triangle_angles_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " triangle angles");
    EXPECT_GE(f.surface.min_angle, 20.0);
    EXPECT_GE(f.surface.fraction_above_40, 0.95);
}

void expect_flat_area_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " flat face areas");
    EXPECT_LE(f.surface.flat_area_error, 1e-3) << f.surface.area_problems;
}

void expect_neighbor_ratio_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " neighbour sizes");
    EXPECT_LE(f.surface.max_neighbor_ratio, 1.5) << f.surface.pairs_above_1_5 << " of " << f.surface.pairs
                                                 << " pairs above 1.5; worst " << f.surface.worst_pair;
}

void expect_pyramid_layer_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " pyramid layer");
    const PyramidAcceptance& p = f.pyramids;
    EXPECT_GT(p.outer_quads, 0u);
    EXPECT_EQ(p.pyramids, p.outer_quads);
    EXPECT_EQ(p.quads_without_one_pyramid, 0u);
    expect_closed("surface triangles + free pyramid triangles", p.front);
    EXPECT_GT(p.min_jacobian, 0.0);
}

void expect_pyramid_quality_accepted(const CaseFigures& f) {
    SCOPED_TRACE(f.name + " pyramid quality");
    EXPECT_GE(f.pyramids.min_jacobian, 0.45);
    EXPECT_GE(f.pyramids.mean_jacobian, 0.80);
}

}  // namespace tubemesh::acceptance
