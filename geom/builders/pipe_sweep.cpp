#include "geom/builders/pipe_sweep.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Circ.hxx>

#include <algorithm>
#include <optional>

#include "engine/core/types.hpp"

namespace tubemesh::geom {

namespace {

std::optional<TopoDS_Solid> only_solid(const TopoDS_Shape& shape) {
    std::optional<TopoDS_Solid> out;
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) {
        if (out) return std::nullopt;
        out = TopoDS::Solid(it.Current());
    }
    if (out && !BRepCheck_Analyzer(*out).IsValid()) return std::nullopt;
    return out;
}

enum class Frame { PlaneNormal, CorrectedFrenet, Discrete };

// MakePipeShell rather than MakePipe for B-spline paths: MakePipe failed (null result or crash)
// on long interpolated paths with straight runs, where the Frenet frame is undefined. The frame
// matters for speed too: along a 3D path the corrected Frenet frame gives walls of several
// times the poles, whose cut is far slower or fails (bench/results/tuning-notes.md).
std::optional<TopoDS_Solid> sweep_shell(const TopoDS_Wire& spine, const TopoDS_Wire& profile, const CentreLine& line,
                                        double radius, Frame frame) {
    BRepOffsetAPI_MakePipeShell sweep(spine);
    switch (frame) {
        case Frame::PlaneNormal: sweep.SetMode(gp_Dir(line.plane_normal.x, line.plane_normal.y, line.plane_normal.z)); break;
        case Frame::CorrectedFrenet: sweep.SetMode(Standard_False); break;
        case Frame::Discrete: sweep.SetDiscreteMode(); break;
    }
    // The default 1e-4 is absolute: too loose for a 0.032 pipe in a 20 m block, needlessly
    // tight for a 12 mm oil hole. Relative to the radius instead. Degree 5 rather than the
    // default 11: walls of fewer poles, and a faster boolean to cut them.
    const double tol = std::clamp(1e-3 * radius, 1e-7, 1e-3);
    sweep.SetTolerance(tol, tol, 1e-3);
    sweep.SetMaxDegree(5);
    sweep.SetMaxSegments(2000);
    sweep.Add(profile);
    sweep.Build();
    if (!sweep.IsDone()) return std::nullopt;
    if (!sweep.MakeSolid()) return std::nullopt;
    return only_solid(sweep.Shape());
}

}  // namespace

TopoDS_Solid sweep_pipe(const CentreLine& line, double diameter, int pipe_number) {
    const std::string label = "pipe " + std::to_string(pipe_number);
    const double radius = diameter / 2;
    try {
        gp_Pnt start;
        gp_Vec tangent;
        line.curve->D1(line.curve->FirstParameter(), start, tangent);
        const gp_Circ circle(gp_Ax2(start, gp_Dir(tangent)), radius);
        const TopoDS_Wire profile = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle));
        const TopoDS_Wire spine = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(line.curve));

        if (line.exact) {
            // Along a line or an arc MakePipe recognises the wall as a cylinder or a torus.
            const TopoDS_Face disc = BRepBuilderAPI_MakeFace(profile);
            BRepOffsetAPI_MakePipe pipe(spine, disc);
            if (pipe.IsDone())
                if (auto solid = only_solid(pipe.Shape())) return *solid;
        } else {
            const Frame first = line.planar ? Frame::PlaneNormal : Frame::Discrete;
            for (Frame frame : {first, Frame::CorrectedFrenet})
                if (auto solid = sweep_shell(spine, profile, line, radius, frame)) return *solid;
        }
    } catch (const Standard_Failure& e) {
        throw Error(label + ": OpenCASCADE failed to sweep the pipe (\"" + std::string(e.GetMessageString()) +
                    "\"): smooth the path or enlarge its bend radii");
    }
    throw Error(label + ": OpenCASCADE could not sweep a valid pipe along the path: smooth the path or enlarge its "
                "bend radii (the tightest bend should be several diameters)");
}

}  // namespace tubemesh::geom
