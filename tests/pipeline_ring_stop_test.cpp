// A ring that stops on a cross-section inside the solid (TubeData::stops), end to end: a pipe
// slightly off square through a box, its wall split by the circle where the ring stops
// (geom::split_wall), the tube cut back to the stretch from its first end (geom::stop_ring_at_edge);
// the wall beyond is meshed with triangles through the ring's wall nodes there, and tets. The mesh
// must be conforming (no hanging node where the ring stops), every cell positive, and every end
// quad of the stopped end must carry a pyramid.
#include <gtest/gtest.h>

#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cstdio>
#include <set>

#include "engine/check/mesh_check.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/mesh_file.hpp"
#include "geom/prepare.hpp"
#include "geom/sizing/discretize_edges.hpp"
#include "geom/tubes/ring_stop.hpp"
#include "tests/support/geom_tubes_solids.hpp"

namespace tubemesh {
namespace {

// The mesh passes the check, the first ring stops at its second end with one stop quad per end
// quad, every front (outer and stopped-end quads) carries one pyramid, and tets fill the rest.
void expect_conforming_with_a_stopped_end(const PipelineResult& r) {
    const CheckReport check = check_mesh(r.mesh);
    EXPECT_TRUE(check.ok()) << describe(check);
    const TubeRing& ring = r.sweep.rings.at(0);
    EXPECT_TRUE(ring.stopped[1]);
    EXPECT_EQ(r.sweep.stop_quads.size(), 4u * ring.radial_layers * ring.circumferential);
    EXPECT_EQ(r.mesh.cell_count(CellKind::Pyramid), (r.sweep.outer_quads.size() + r.sweep.stop_quads.size()) / 4);
    EXPECT_GT(r.mesh.cell_count(CellKind::Tet), 0u);
}

// The closed edge two of the tube's wall faces share (not a seam): where its wall was split.
int split_edge(const geom::Model& model, const TubeData& tube) {
    std::vector<TopTools_IndexedMapOfShape> edges(tube.wall_faces.size());
    for (std::size_t i = 0; i < edges.size(); ++i)
        TopExp::MapShapes(geom::face_of(model, static_cast<int>(tube.wall_faces[i])), TopAbs_EDGE, edges[i]);
    for (std::size_t i = 0; i < edges.size(); ++i)
        for (std::size_t j = i + 1; j < edges.size(); ++j)
            for (int k = 1; k <= edges[i].Extent(); ++k)
                if (edges[j].Contains(edges[i](k)) && BRep_Tool::IsClosed(TopoDS::Edge(edges[i](k))))
                    return geom::edge_id(model, edges[i](k));
    return 0;
}

TEST(PipelineRingStop, ARingThatStopsMeetsTetsConformingly) {
    // Radius 0.02 along (0, 0.1, 1): about 6 degrees off square to the top and bottom faces.
    const TopoDS_Solid solid = test::box_with_pipes(
        gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 1), {test::straight_spine(gp_Pnt(0.5, 0.4, -0.5), gp_Pnt(0.5, 0.6, 1.5))}, 0.02);
    const geom::Model whole = test::model_of(solid);
    const geom::PreparedModel first = geom::prepare_model(whole);
    ASSERT_EQ(first.geometry.tubes.size(), 1u);
    const TubeData& t0 = first.geometry.tubes[0];
    ASSERT_EQ(t0.wall_faces.size(), 1u);
    const TubeStation& at = t0.stations[t0.stations.size() * 3 / 5];
    const geom::Model model = geom::split_wall(whole, static_cast<int>(t0.wall_faces[0]), at.centre, at.tangent);
    EXPECT_EQ(model.face_count(), whole.face_count() + 1);

    geom::PreparedModel prepared = geom::prepare_model(model);
    ASSERT_EQ(prepared.geometry.tubes.size(), 1u);
    TubeData& tube = prepared.geometry.tubes[0];
    ASSERT_EQ(tube.wall_faces.size(), 2u);
    const int edge = split_edge(model, tube);
    ASSERT_GT(edge, 0);
    geom::stop_ring_at_edge(model, edge, tube);
    EXPECT_EQ(tube.wall_faces.size(), 1u);
    EXPECT_TRUE(tube.stops[1]);
    // The edges of the faces beyond get polylines now: only the ring's own face's are skipped.
    std::set<int> skip;
    TopTools_IndexedMapOfShape ring_edges;
    TopExp::MapShapes(geom::face_of(model, static_cast<int>(tube.wall_faces[0])), TopAbs_EDGE, ring_edges);
    for (int k = 1; k <= ring_edges.Extent(); ++k) skip.insert(geom::edge_id(model, ring_edges(k)));
    prepared.geometry.edges = geom::discretize_edges(model, skip, prepared.plan.size, kDefaultChordal);

    const PipelineResult r = run_pipeline(prepared.pipeline_input());
    std::printf("[ figures  ] hexes %u pyramids %u tets %u, stop quads %zu\n", r.mesh.cell_count(CellKind::Hex),
                r.mesh.cell_count(CellKind::Pyramid), r.mesh.cell_count(CellKind::Tet), r.sweep.stop_quads.size() / 4);
    expect_conforming_with_a_stopped_end(r);
    const TubeRing& ring = r.sweep.rings.at(0);
    // The ring's nodes reach the plane where it stops and no further.
    double ahead = -1;
    for (index_t i = ring.first_node; i < ring.first_node + ring.stations * (ring.radial_layers + 1) * ring.circumferential; ++i)
        ahead = std::max(ahead, dot(r.mesh.point(i) - tube.stations.back().centre, tube.stations.back().tangent));
    EXPECT_NEAR(ahead, 0, 1e-9);

    // The same mesh for one thread and two.
    MeshOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const PipelineResult a = run_pipeline(prepared.pipeline_input(), one), b = run_pipeline(prepared.pipeline_input(), two);
    EXPECT_EQ(a.mesh.x, b.mesh.x);
    EXPECT_EQ(a.mesh.y, b.mesh.y);
    EXPECT_EQ(a.mesh.z, b.mesh.z);
    for (CellKind k : {CellKind::Hex, CellKind::Pyramid, CellKind::Tet})
        EXPECT_EQ(a.mesh.block(k).nodes, b.mesh.block(k).nodes);
}

// An inclined pipe whose wall comes within 0.005 r of the bottom face near its right end: no ring
// fits there, but one fits along the rest. prepare_model splits the wall a diameter before that
// spot, stops the ring there, and meshes the wall beyond with tets.
TEST(PipelineRingStop, APipeTooNearAFaceAtOneEndKeepsItsRingOnTheRest) {
    const double r = 0.02;
    const TopoDS_Solid solid = test::box_with_pipes(
        gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 1), {test::straight_spine(gp_Pnt(-0.5, 0.5, 0.441), gp_Pnt(1.5, 0.5, -0.119))}, r);
    const geom::Model model = test::model_of(solid);
    const geom::PreparedModel prepared = geom::prepare_model(model, geom::prepare_options(MeshOptions{}));
    ASSERT_TRUE(prepared.split != nullptr);
    EXPECT_EQ(prepared.split->face_count(), model.face_count() + 1);
    // Every face but the split wall is found again in the split model (the retry's drops move there).
    const std::vector<int> same = geom::same_faces_in(model, *prepared.split);
    EXPECT_EQ(std::count(same.begin(), same.end(), 0), 1);
    EXPECT_EQ(std::set<int>(same.begin(), same.end()).size(), same.size());
    ASSERT_EQ(prepared.tubes.tubes.size(), 1u);
    ASSERT_TRUE(prepared.tubes.tubes[0].stop.has_value());
    EXPECT_TRUE(prepared.dropped.empty());
    const double share = geom::ring_share(prepared.coverage);
    std::printf("[ figures  ] ring share %.3f\n", share);
    EXPECT_GT(share, 0.3);
    EXPECT_LT(share, 0.98);
    // The coverage says where the ring stops and why.
    ASSERT_EQ(prepared.coverage.size(), 1u);
    const geom::RingCoverage& c = prepared.coverage[0];
    EXPECT_GT(c.length, c.ring_length);
    EXPECT_NEAR(c.share, c.ring_length / c.length, 1e-12);
    EXPECT_NE(c.reason.find("ring stops before a spot"), std::string::npos) << c.reason;
    EXPECT_EQ(c.faces.size(), 2u);
    const TubeData& tube = prepared.geometry.tubes.at(0);
    EXPECT_TRUE(tube.stops[1]);

    MeshOptions one, two;
    one.threads = 1;
    two.threads = 2;
    // The whole run, with its retries: the stopped ring's pyramids may need a thinner St.
    const geom::MeshRun run_one = geom::mesh_model(model, one), run_two = geom::mesh_model(model, two);
    const PipelineResult &a = run_one.result, &b = run_two.result;
    EXPECT_GT(geom::ring_share(run_one.coverage), 0.0);
    EXPECT_LT(geom::ring_share(run_one.coverage), 1.0);
    expect_conforming_with_a_stopped_end(a);
    // The stopped end's rim is no outlet: the pipe goes on with tets.
    std::vector<std::string> rims;
    for (const NamedNodeSet& s : a.description.node_sets) rims.push_back(s.name);
    EXPECT_EQ(rims, (std::vector<std::string>{"pipe_1_inlet", "pipe_1_ring_stop"}));
    EXPECT_EQ(a.mesh.x, b.mesh.x);
    EXPECT_EQ(a.mesh.y, b.mesh.y);
    EXPECT_EQ(a.mesh.z, b.mesh.z);
    for (CellKind k : {CellKind::Hex, CellKind::Pyramid, CellKind::Tet})
        EXPECT_EQ(a.mesh.block(k).nodes, b.mesh.block(k).nodes);
}

}  // namespace
}  // namespace tubemesh
