// A ring that stops on a cross-section inside the solid (TubeData::stops), end to end: a pipe
// whose wall is two faces split by a circle, the ring on the lower face only, stopped at the
// circle; the upper face is meshed with triangles through the ring's wall nodes there and tets.
// The mesh must be conforming (no hanging node where the ring stops), every cell positive, and
// every end quad of the stopped end must carry a pyramid.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <ElCLib.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "engine/check/mesh_check.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/prepare.hpp"
#include "geom/sizing/discretize_edges.hpp"
#include "tests/support/geom_tubes_solids.hpp"

namespace tubemesh {
namespace {

constexpr double kR = 0.02, kCut = 0.6;

// The unit box minus a pipe of radius kR along x = y = 0.5, its wall two faces meeting at z = kCut.
// The ring runs from the top face (ring1's end, as the tube search orders it) down to the cut.
TopoDS_Solid box_with_split_pipe() {
    const gp_Ax2 low(gp_Pnt(0.5, 0.5, -0.5), gp_Dir(0, 0, 1)), high(gp_Pnt(0.5, 0.5, kCut), gp_Dir(0, 0, 1));
    const TopoDS_Shape tool = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeCylinder(low, kR, kCut + 0.5).Shape(),
                                               BRepPrimAPI_MakeCylinder(high, kR, 1.5 - kCut).Shape())
                                  .Shape();
    const TopoDS_Shape cut = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 1)).Shape(), tool).Shape();
    TopExp_Explorer it(cut, TopAbs_SOLID);
    return TopoDS::Solid(it.Current());
}

// The prepared tube turned into a ring on its first end's stretch of wall that stops at the cut.
void stop_at_cut(const geom::Model& model, geom::PreparedModel& prepared) {
    TubeData& t = prepared.geometry.tubes.at(0);
    ASSERT_EQ(t.wall_faces.size(), 2u);
    const double z1 = t.stations.front().centre.z;  // ring1's end: the ring runs from there to the cut
    // The wall faces and the circle they share.
    int low = 0, high = 0, circle = 0;
    // The ring's face reaches ring1's end; the other lies beyond the cut.
    for (index_t f : t.wall_faces) {
        double nearest = 1e9;
        for (TopExp_Explorer e(geom::face_of(model, static_cast<int>(f)), TopAbs_VERTEX); e.More(); e.Next())
            nearest = std::min(nearest, std::abs(BRep_Tool::Pnt(TopoDS::Vertex(e.Current())).Z() - z1));
        (nearest < 1e-6 ? low : high) = static_cast<int>(f);
    }
    ASSERT_NE(low, high);
    TopTools_IndexedMapOfShape low_edges, high_edges;
    TopExp::MapShapes(geom::face_of(model, low), TopAbs_EDGE, low_edges);
    TopExp::MapShapes(geom::face_of(model, high), TopAbs_EDGE, high_edges);
    for (int i = 1; i <= low_edges.Extent(); ++i)
        if (high_edges.Contains(low_edges(i)) && !BRep_Tool::IsClosed(TopoDS::Edge(low_edges(i)), geom::face_of(model, low)))
            circle = geom::edge_id(model, low_edges(i));
    ASSERT_GT(circle, 0);
    const TopoDS_Edge edge = geom::edge_of(model, circle);
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edge, v0, v1);
    TopTools_IndexedMapOfShape vertices;
    TopExp::MapShapes(geom::solid_of(model), TopAbs_VERTEX, vertices);
    const gp_Pnt corner = BRep_Tool::Pnt(v0);

    t.wall_faces = {static_cast<index_t>(low)};
    t.host2 = static_cast<index_t>(high);
    t.loop2_edges = {static_cast<index_t>(circle)};
    t.stops = {false, true};
    t.stop_vertex[1] = static_cast<index_t>(vertices.FindIndex(v0));
    // Stations up to the cut, the last one on it.
    const TubeStation last = t.stations.back();
    const double spacing = std::abs(t.stations[1].centre.z - z1);
    std::erase_if(t.stations, [&](const TubeStation& s) { return std::abs(s.centre.z - z1) > std::abs(kCut - z1) - spacing / 2; });
    t.stations.push_back({{0.5, 0.5, kCut}, last.tangent, last.reference, kR});
    // Ring2 on the circle from its vertex, turning as ring1 does; the circle's parameter at each node.
    const int n = static_cast<int>(t.ring1.size());
    const double a1 = std::atan2(t.ring1[1].y - 0.5, t.ring1[1].x - 0.5) - std::atan2(t.ring1[0].y - 0.5, t.ring1[0].x - 0.5);
    const double turn = std::remainder(a1, 2 * std::numbers::pi) > 0 ? 1.0 : -1.0;
    const double a0 = std::atan2(corner.Y() - 0.5, corner.X() - 0.5);
    const BRepAdaptor_Curve curve(edge);
    const double first = curve.FirstParameter(), last_param = curve.LastParameter();
    const double step = (last_param - first) / n;
    // Along the edge the circle turns one way: the ring's way or the other.
    const gp_Pnt ahead = curve.Value(first + step);
    const double edge_turn =
        std::remainder(std::atan2(ahead.Y() - 0.5, ahead.X() - 0.5) - a0, 2 * std::numbers::pi) > 0 ? 1.0 : -1.0;
    t.ring2.clear();
    t.stop_params[1].clear();
    for (int k = 0; k <= n; ++k) {
        const double a = a0 + turn * 2 * std::numbers::pi * k / n;
        if (k < n) t.ring2.push_back({0.5 + kR * std::cos(a), 0.5 + kR * std::sin(a), kCut});
        t.stop_params[1].push_back(turn == edge_turn ? first + k * step : last_param - k * step);
    }
    // The edges of the upper face get polylines now: only the ring's own face's are skipped.
    std::set<int> skip;
    for (int i = 1; i <= low_edges.Extent(); ++i) skip.insert(geom::edge_id(model, low_edges(i)));
    prepared.geometry.edges = geom::discretize_edges(model, skip, prepared.plan.size, kDefaultChordal);
}

TEST(PipelineRingStop, ARingThatStopsMeetsTetsConformingly) {
    const geom::Model model = test::model_of(box_with_split_pipe());
    geom::PreparedModel prepared = geom::prepare_model(model);
    for (const auto& rj : prepared.tubes.rejected) ADD_FAILURE() << "rejected: " << rj.reason;
    for (const auto& d : prepared.dropped) ADD_FAILURE() << "dropped: " << d.reason;
    ASSERT_EQ(prepared.tubes.tubes.size(), 1u);
    stop_at_cut(model, prepared);
    if (HasFatalFailure()) return;
    const PipelineResult r = run_pipeline(prepared.pipeline_input());
    std::printf("[ figures  ] hexes %u pyramids %u tets %u, stop quads %zu\n", r.mesh.cell_count(CellKind::Hex),
                r.mesh.cell_count(CellKind::Pyramid), r.mesh.cell_count(CellKind::Tet), r.sweep.stop_quads.size() / 4);
    const CheckReport check = check_mesh(r.mesh);
    EXPECT_TRUE(check.ok()) << describe(check);
    const TubeRing& ring = r.sweep.rings.at(0);
    EXPECT_TRUE(ring.stopped[1]);
    EXPECT_EQ(r.sweep.stop_quads.size(), 4u * ring.radial_layers * ring.circumferential);
    // One pyramid per front: the outer quads and the stopped end's quads.
    EXPECT_EQ(r.mesh.cell_count(CellKind::Pyramid), (r.sweep.outer_quads.size() + r.sweep.stop_quads.size()) / 4);
    EXPECT_GT(r.mesh.cell_count(CellKind::Tet), 0u);
    // The ring's hexes reach the cut and no further.
    double lo = 1, hi = 0;
    for (index_t i = ring.first_node; i < ring.first_node + ring.stations * (ring.radial_layers + 1) * ring.circumferential; ++i) {
        lo = std::min(lo, r.mesh.point(i).z);
        hi = std::max(hi, r.mesh.point(i).z);
    }
    EXPECT_NEAR(std::min(std::abs(lo - kCut), std::abs(hi - kCut)), 0, 1e-9);
    EXPECT_NEAR(hi - lo, std::abs(1 - kCut), 1e-9);  // from the top face to the cut
}

}  // namespace
}  // namespace tubemesh
