#include "tests/support/geom_tubes_solids.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <unistd.h>

#include "geom/model/model_occt.hpp"

namespace tubemesh::test {
namespace {

TopoDS_Solid first_solid(const TopoDS_Shape& shape) {
    TopExp_Explorer it(shape, TopAbs_SOLID);
    if (!it.More()) throw std::runtime_error("no solid in the shape");
    return TopoDS::Solid(it.Current());
}

TopoDS_Shape pipe(const TopoDS_Wire& spine, double r) {
    // The profile circle sits at the spine's start, normal to its tangent.
    TopExp_Explorer first(spine, TopAbs_EDGE);
    BRepAdaptor_Curve c(TopoDS::Edge(first.Current()));
    gp_Pnt p;
    gp_Vec t;
    const bool reversed = first.Current().Orientation() == TopAbs_REVERSED;
    c.D1(reversed ? c.LastParameter() : c.FirstParameter(), p, t);
    if (reversed) t.Reverse();
    const gp_Circ circle(gp_Ax2(p, gp_Dir(t)), r);
    const TopoDS_Face profile =
        BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire()).Face();
    BRepOffsetAPI_MakePipe maker(spine, profile);
    maker.Build();
    if (!maker.IsDone()) throw std::runtime_error("MakePipe failed");
    return maker.Shape();
}

TopoDS_Shape unit_box() { return BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 1, 1, 1).Shape(); }

TopoDS_Solid cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
    BRepAlgoAPI_Cut op(a, b);
    if (!op.IsDone()) throw std::runtime_error("boolean cut failed");
    return first_solid(op.Shape());
}

}  // namespace

TopoDS_Wire straight_spine(const gp_Pnt& a, const gp_Pnt& b) {
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(a, b).Edge()).Wire();
}

TopoDS_Wire arc_spine(const gp_Pnt& centre, double radius, double a0_deg, double a1_deg) {
    const gp_Circ circle(gp_Ax2(centre, gp_Dir(0, 0, 1)), radius);
    const double d = std::numbers::pi / 180;
    Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(circle, a0_deg * d, a1_deg * d, true).Value();
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(arc).Edge()).Wire();
}

TopoDS_Wire corner_spine(const gp_Pnt& a, const gp_Pnt& corner, const gp_Pnt& b, double bend) {
    BRepBuilderAPI_MakeWire wire;
    if (bend <= 0) {
        wire.Add(BRepBuilderAPI_MakeEdge(a, corner).Edge());
        wire.Add(BRepBuilderAPI_MakeEdge(corner, b).Edge());
        return wire.Wire();
    }
    const gp_Vec d1 = gp_Vec(a, corner).Normalized(), d2 = gp_Vec(corner, b).Normalized();
    const double t = bend * std::tan(d1.Angle(d2) / 2);  // corner to the arc's tangent points
    const gp_Pnt p1 = corner.Translated(-d1 * t), p2 = corner.Translated(d2 * t);
    Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(p1, d1, p2).Value();
    wire.Add(BRepBuilderAPI_MakeEdge(a, p1).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(arc).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(p2, b).Edge());
    return wire.Wire();
}

TopoDS_Wire spline_spine(const std::vector<gp_Pnt>& points) {
    Handle(TColgp_HArray1OfPnt) array = new TColgp_HArray1OfPnt(1, static_cast<int>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) array->SetValue(static_cast<int>(i) + 1, points[i]);
    GeomAPI_Interpolate interpolate(array, false, 1e-9);
    interpolate.Perform();
    Handle(Geom_BSplineCurve) curve = interpolate.Curve();
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve).Edge()).Wire();
}

TopoDS_Solid box_with_pipes(const gp_Pnt& lo, const gp_Pnt& hi, const std::vector<TopoDS_Wire>& spines, double r) {
    TopoDS_Shape shape = BRepPrimAPI_MakeBox(lo, hi).Shape();
    for (const TopoDS_Wire& spine : spines) shape = cut(shape, pipe(spine, r));
    return first_solid(shape);
}

TopoDS_Solid box_with_blind_hole(double r, double depth) {
    const gp_Ax2 axis(gp_Pnt(0.5, 0.5, 1 - depth), gp_Dir(0, 0, 1));
    return cut(unit_box(), BRepPrimAPI_MakeCylinder(axis, r, depth + 0.5).Shape());
}

TopoDS_Solid box_with_slot(double width, double length) {
    const gp_Pnt lo(0.5 - length / 2, 0.5 - width / 2, -0.5);
    return cut(unit_box(), BRepPrimAPI_MakeBox(lo, length, width, 2).Shape());
}

TopoDS_Solid box_with_pocket(double width, double depth) {
    const gp_Pnt lo(0.5 - width / 2, 0.5 - width / 2, 1 - depth);
    return cut(unit_box(), BRepPrimAPI_MakeBox(lo, width, width, depth + 0.5).Shape());
}

TopoDS_Solid pipe_solid(const TopoDS_Wire& spine, double r) { return first_solid(pipe(spine, r)); }

TopoDS_Solid split_closed_faces(const TopoDS_Shape& shape) {
    ShapeUpgrade_ShapeDivideClosed divide(shape);
    divide.SetNbSplitPoints(1);
    if (!divide.Perform()) throw std::runtime_error("ShapeDivideClosed changed nothing");
    return first_solid(divide.Result());
}

TopoDS_Solid step_round_trip(const TopoDS_Shape& shape) {
    // The writer's transfer banner goes to the default printer: keep test output clean.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("tubemesh_geom_test_" + std::to_string(::getpid()) + ".step");
    STEPControl_Writer writer;
    if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("STEP write failed");
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("STEP read failed");
    reader.TransferRoots();
    const TopoDS_Shape back = reader.OneShape();
    std::filesystem::remove(path);
    return first_solid(back);
}

geom::Model model_of(const TopoDS_Solid& solid) {
    geom::ImportReport report;
    report.source = "test";
    report.format = "built";
    return geom::make_model(solid, report);
}

}  // namespace tubemesh::test
