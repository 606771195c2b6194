#include "geom/builders/path_pieces.hpp"

#include <GC_MakeArcOfCircle.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfBoolean.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfVec.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "engine/core/types.hpp"
#include "geom/builders/host_geometry.hpp"
#include "geom/builders/occt_convert.hpp"

namespace tubemesh::geom {

namespace {

constexpr double kPi = std::numbers::pi;

std::string pipe_label(int n) { return "pipe " + std::to_string(n); }

Handle(Geom_Curve) segment(const Vec3& a, const Vec3& b) {
    const double len = norm(b - a);
    return new Geom_TrimmedCurve(new Geom_Line(to_pnt(a), gp_Dir(to_vec(b - a))), 0.0, len);
}

PathPieces polyline_pieces(const PipeSpec& pipe, int number) {
    const std::vector<Vec3>& p = pipe.points;
    const std::size_t n = p.size();
    const double r = pipe.diameter / 2;
    const double R = pipe.bend_radius;
    // Tangent length at each interior corner: R tan(turn / 2).
    std::vector<double> cut(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const Vec3 u = unit(p[i] - p[i - 1]), v = unit(p[i + 1] - p[i]);
        const double turn = std::acos(std::clamp(dot(u, v), -1.0, 1.0));
        if (turn < 1e-9) continue;  // collinear: no bend
        if (turn > kPi - 1e-3)
            throw Error(pipe_label(number) + ": the polyline turns back on itself at point " + std::to_string(i + 1));
        if (R <= 0)
            throw Error(pipe_label(number) + ": a polyline with corners needs a bend_radius (larger than the pipe radius)");
        if (R <= 1.05 * r)
            throw Error(pipe_label(number) + ": bend_radius " + std::to_string(R) +
                        " is too small for the pipe radius " + std::to_string(r) + " (the wall would fold over itself)");
        cut[i] = R * std::tan(turn / 2);
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double len = norm(p[i + 1] - p[i]);
        if (cut[i] + cut[i + 1] > len * (1 + 1e-9))
            throw Error(pipe_label(number) + ": bend_radius " + std::to_string(R) + " does not fit segment " +
                        std::to_string(i + 1) + " (length " + std::to_string(len) + "): use a smaller radius or longer segments");
    }
    PathPieces out;
    Vec3 at = p[0];
    for (std::size_t i = 1; i < n; ++i) {
        const Vec3 u = unit(p[i] - p[i - 1]);
        const Vec3 corner_in = p[i] - cut[i] * u;
        if (norm(corner_in - at) > Precision::Confusion()) {
            out.curves.push_back(segment(at, corner_in));
            out.straight.push_back(true);
        }
        at = corner_in;
        if (cut[i] > 0) {
            const Vec3 v = unit(p[i + 1] - p[i]);
            const Vec3 corner_out = p[i] + cut[i] * v;
            GC_MakeArcOfCircle arc(to_pnt(corner_in), to_vec(u), to_pnt(corner_out));
            out.curves.push_back(arc.Value());
            out.straight.push_back(false);
            at = corner_out;
        }
    }
    return out;
}

Handle(Geom_Curve) spline_through(const PipeSpec& pipe, const HostSpec& host, int number) {
    const int n = static_cast<int>(pipe.points.size());
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, n);
    for (int i = 0; i < n; ++i) points->SetValue(i + 1, to_pnt(pipe.points[static_cast<std::size_t>(i)]));
    GeomAPI_Interpolate interpolate(points, Standard_False, Precision::Confusion());
    // Ends on a face meet it at a right angle unless told otherwise: oblique ends make long
    // elliptical hole rims that mesh poorly.
    const double tol = 1e-9 * host_extent(host);
    std::optional<Vec3> t0 = pipe.start_tangent, t1 = pipe.end_tangent;
    if (!t0) {
        if (auto n0 = boundary_normal(host, pipe.points.front(), tol)) t0 = -1.0 * *n0;
    }
    if (!t1) {
        if (auto n1 = boundary_normal(host, pipe.points.back(), tol)) t1 = *n1;
    }
    if (t0 || t1) {
        TColgp_Array1OfVec tangents(1, n);
        Handle(TColStd_HArray1OfBoolean) flags = new TColStd_HArray1OfBoolean(1, n);
        for (int i = 1; i <= n; ++i) {
            tangents(i) = gp_Vec(1, 0, 0);
            flags->SetValue(i, Standard_False);
        }
        if (t0) tangents(1) = to_vec(unit(*t0)), flags->SetValue(1, Standard_True);
        if (t1) tangents(n) = to_vec(unit(*t1)), flags->SetValue(n, Standard_True);
        interpolate.Load(tangents, flags, Standard_True);
    }
    interpolate.Perform();
    if (!interpolate.IsDone())
        throw Error(pipe_label(number) + ": cannot interpolate a spline through its points (are two of them equal?)");
    return Handle(Geom_Curve)(interpolate.Curve());
}

Handle(Geom_Curve) bspline_from_poles(const PipeSpec& pipe) {
    const int n = static_cast<int>(pipe.points.size());
    const int degree = std::min(3, n - 1);
    const int knots = n - degree + 1;
    TColgp_Array1OfPnt poles(1, n);
    for (int i = 0; i < n; ++i) poles(i + 1) = to_pnt(pipe.points[static_cast<std::size_t>(i)]);
    TColStd_Array1OfReal knot_values(1, knots);
    TColStd_Array1OfInteger mults(1, knots);
    for (int i = 1; i <= knots; ++i) {
        knot_values(i) = static_cast<double>(i - 1) / (knots - 1);
        mults(i) = (i == 1 || i == knots) ? degree + 1 : 1;
    }
    return new Geom_BSplineCurve(poles, knot_values, mults, degree);
}

}  // namespace

PathPieces path_pieces(const PipeSpec& pipe, const HostSpec& host, int pipe_number) {
    if (pipe.kind == PathKind::Polyline) return polyline_pieces(pipe, pipe_number);
    PathPieces out;
    out.curves.push_back(pipe.kind == PathKind::Spline ? spline_through(pipe, host, pipe_number) : bspline_from_poles(pipe));
    out.straight.push_back(false);
    return out;
}

}  // namespace tubemesh::geom
