#include "geom/builders/centre_line.hpp"

#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomLProp_CLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfBoolean.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfVec.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/core/types.hpp"
#include "geom/builders/host_geometry.hpp"
#include "geom/builders/occt_convert.hpp"
#include "geom/builders/path_pieces.hpp"

namespace tubemesh::geom {

namespace {

constexpr double kPi = std::numbers::pi;

std::string pipe_label(int n) { return "pipe " + std::to_string(n); }

// Far enough past the end that the pipe's end cap is clear of the host even where the path meets
// the boundary at an angle, short enough not to matter for the boolean's speed.
double extension_length(const PipeSpec& pipe, const HostSpec& host) {
    return std::max(3.0 * pipe.diameter, 0.02 * host_extent(host));
}

// A point with its unit direction of travel: what the C2 re-interpolation needs.
struct Sample {
    Vec3 p;
    Vec3 t;
};

// Samples along one piece of a composite path, `count` + 1 of them, evenly spaced by arc length.
void sample_piece(const Handle(Geom_Curve)& piece, int count, std::vector<Sample>& out) {
    GeomAdaptor_Curve adaptor(piece);
    GCPnts_UniformAbscissa uniform(adaptor, count + 1);
    const bool by_length = uniform.IsDone() && uniform.NbPoints() == count + 1;
    const double f = piece->FirstParameter(), l = piece->LastParameter();
    // A piece's first sample repeats the previous piece's last one: skip it after the first piece.
    for (int i = out.empty() ? 0 : 1; i <= count; ++i) {
        const double u = by_length ? uniform.Parameter(i + 1) : f + (l - f) * i / count;
        gp_Pnt p;
        gp_Vec d1;
        piece->D1(u, p, d1);
        out.push_back({to_vec3(p.XYZ()), unit(to_vec3(d1.XYZ()))});
    }
}

double curve_length(const Handle(Geom_Curve)& c, double u0, double u1) {
    GeomAdaptor_Curve adaptor(c, u0, u1);
    return GCPnts_AbscissaPoint::Length(adaptor);
}

double sampled_min_radius(const Handle(Geom_Curve)& c, double u0, double u1, int samples) {
    GeomLProp_CLProps props(c, 2, Precision::Confusion());
    double min_radius = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= samples; ++i) {
        props.SetParameter(u0 + (u1 - u0) * i / samples);
        const double k = props.Curvature();
        if (k > 1e-12) min_radius = std::min(min_radius, 1.0 / k);
    }
    return min_radius;
}

// One C2 B-spline through samples of a composite path (pieces joined with matching tangents),
// interpolating positions and tangents at every sample. Chord-length parameters make unit
// tangents the right size, so straight runs stay straight and arcs stay round to well below
// the pipe radius (checked in the builders' tests).
Handle(Geom_BSplineCurve) reinterpolate(const std::vector<Sample>& samples, double tolerance) {
    const int n = static_cast<int>(samples.size());
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, n);
    Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, n);
    TColgp_Array1OfVec tangents(1, n);
    Handle(TColStd_HArray1OfBoolean) flags = new TColStd_HArray1OfBoolean(1, n);
    double u = 0;
    for (int i = 0; i < n; ++i) {
        if (i > 0) u += norm(samples[i].p - samples[i - 1].p);
        points->SetValue(i + 1, to_pnt(samples[i].p));
        params->SetValue(i + 1, u);
        tangents(i + 1) = to_vec(samples[i].t);
        flags->SetValue(i + 1, Standard_True);
    }
    GeomAPI_Interpolate interpolate(points, params, Standard_False, tolerance);
    interpolate.Load(tangents, flags, Standard_False);
    interpolate.Perform();
    if (!interpolate.IsDone()) return nullptr;
    return interpolate.Curve();
}

// How many samples a piece needs: arcs every 15 degrees, curved pieces at a quarter of their
// tightest radius and at least 16, straight pieces at `line_spacing`.
int sample_count(const Handle(Geom_Curve)& piece, bool straight, double line_spacing) {
    const double len = curve_length(piece, piece->FirstParameter(), piece->LastParameter());
    if (straight) return std::max(1, static_cast<int>(std::ceil(len / line_spacing)));
    auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(piece);
    if (!trimmed.IsNull() && trimmed->BasisCurve()->IsKind(STANDARD_TYPE(Geom_Circle))) {
        const double angle = trimmed->LastParameter() - trimmed->FirstParameter();
        return std::max(2, static_cast<int>(std::ceil(angle / (kPi / 12))));
    }
    const double radius = sampled_min_radius(piece, piece->FirstParameter(), piece->LastParameter(), 400);
    const double h = std::min(len / 16, radius / 4);
    return std::clamp(static_cast<int>(std::ceil(len / h)), 16, 4000);
}

double piece_spacing(const Handle(Geom_Curve)& piece, int count) {
    return curve_length(piece, piece->FirstParameter(), piece->LastParameter()) / count;
}

// Plane through the samples, if they have one: the sweep then keeps the circle's frame fixed
// to the plane normal, which is exact and cannot twist.
void detect_plane(const std::vector<Sample>& samples, double extent, CentreLine& line) {
    const Vec3 p0 = samples.front().p;
    std::size_t far = 0;
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (norm(samples[i].p - p0) > norm(samples[far].p - p0)) far = i;
    const Vec3 a = samples[far].p - p0;
    Vec3 best{0, 0, 0};
    for (const Sample& s : samples) {
        const Vec3 c = cross(a, s.p - p0);
        if (norm(c) > norm(best)) best = c;
    }
    if (norm(best) < 1e-12 * extent * extent) return;  // collinear: the sweep needs no plane
    const Vec3 normal = unit(best);
    for (const Sample& s : samples)
        if (std::abs(dot(s.p - p0, normal)) > 1e-9 * extent) return;
    line.planar = true;
    line.plane_normal = normal;
}

CentreLine line_centre_line(const PipeSpec& pipe, double e, int number) {
    if (pipe.points.size() != 2)
        throw Error(pipe_label(number) + ": a line needs exactly 2 points, got " + std::to_string(pipe.points.size()));
    const Vec3 a = pipe.points[0], b = pipe.points[1];
    const double len = norm(b - a);
    if (len <= Precision::Confusion()) throw Error(pipe_label(number) + ": the line's two points are the same");
    CentreLine line;
    line.curve = new Geom_TrimmedCurve(new Geom_Line(to_pnt(a), gp_Dir(to_vec(b - a))), -e, pipe.blind ? len : len + e);
    line.exact = true;
    line.extension = e;
    line.path_first = 0;
    line.path_last = len;
    return line;
}

CentreLine arc_centre_line(const PipeSpec& pipe, double e, int number) {
    if (pipe.points.size() != 3)
        throw Error(pipe_label(number) + ": an arc needs 3 points (start, a point on the arc, end), got " +
                    std::to_string(pipe.points.size()));
    GC_MakeArcOfCircle make(to_pnt(pipe.points[0]), to_pnt(pipe.points[1]), to_pnt(pipe.points[2]));
    if (!make.IsDone()) throw Error(pipe_label(number) + ": the arc's 3 points are collinear or coincide");
    const Handle(Geom_TrimmedCurve)& arc = make.Value();
    Handle(Geom_Circle) circle = Handle(Geom_Circle)::DownCast(arc->BasisCurve());
    const double de = e / circle->Radius();
    const double span = arc->LastParameter() - arc->FirstParameter();
    if (span + 2 * de > 2 * kPi - 1e-3)
        throw Error(pipe_label(number) + ": the arc is (nearly) a full circle: it cannot enter and leave the block");
    CentreLine line;
    Handle(Geom_TrimmedCurve) extended = new Geom_TrimmedCurve(circle, arc->FirstParameter() - de, arc->LastParameter() + de);
    line.curve = extended;
    line.exact = true;
    line.planar = true;
    const gp_Dir axis = circle->Axis().Direction();
    line.plane_normal = {axis.X(), axis.Y(), axis.Z()};
    line.extension = e;
    // Trimming a periodic curve may shift its parameters by a period: read them back.
    line.path_first = extended->FirstParameter() + de;
    line.path_last = extended->LastParameter() - de;
    return line;
}

}  // namespace

CentreLine make_centre_line(const PipeSpec& pipe, const HostSpec& host, int number) {
    if (!(pipe.diameter > 0)) throw Error(pipe_label(number) + ": the diameter must be positive");
    const std::size_t min_points = pipe.kind == PathKind::Arc ? 3 : 2;
    if (pipe.points.size() < min_points)
        throw Error(pipe_label(number) + ": needs at least " + std::to_string(min_points) + " points, got " +
                    std::to_string(pipe.points.size()));
    for (std::size_t i = 1; i < pipe.points.size(); ++i)
        if (norm(pipe.points[i] - pipe.points[i - 1]) <= Precision::Confusion())
            throw Error(pipe_label(number) + ": points " + std::to_string(i) + " and " + std::to_string(i + 1) + " coincide");

    const double e = extension_length(pipe, host);
    if (pipe.kind == PathKind::Line) return line_centre_line(pipe, e, number);
    if (pipe.kind == PathKind::Arc) return arc_centre_line(pipe, e, number);
    if (pipe.kind == PathKind::Polyline && pipe.points.size() == 2) {
        PipeSpec as_line = pipe;
        as_line.kind = PathKind::Line;
        return line_centre_line(as_line, e, number);
    }

    const PathPieces body = path_pieces(pipe, host, number);

    // Straight runs are sampled about as densely as the curved pieces next to them (4 times
    // sparser): far sparser samples would let the interpolant wiggle where a run meets a bend.
    std::vector<int> counts(body.curves.size());
    double curved_spacing = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < body.curves.size(); ++i) {
        if (body.straight[i]) continue;
        counts[i] = sample_count(body.curves[i], false, 0);
        curved_spacing = std::min(curved_spacing, piece_spacing(body.curves[i], counts[i]));
    }
    const double line_spacing = std::isfinite(curved_spacing) ? 4 * curved_spacing : host_extent(host) / 16;
    for (std::size_t i = 0; i < body.curves.size(); ++i)
        if (body.straight[i]) counts[i] = sample_count(body.curves[i], true, line_spacing);

    std::vector<Sample> samples;
    for (std::size_t i = 0; i < body.curves.size(); ++i) sample_piece(body.curves[i], counts[i], samples);

    // Straight extensions along the end tangents, sampled like the straight runs.
    const Sample first = samples.front(), last = samples.back();
    const int ext_count = std::max(1, static_cast<int>(std::ceil(e / line_spacing)));
    std::vector<Sample> all;
    for (int i = 0; i < ext_count; ++i) all.push_back({first.p - (e * (ext_count - i) / ext_count) * first.t, first.t});
    all.insert(all.end(), samples.begin(), samples.end());
    for (int i = 1; i <= ext_count; ++i) all.push_back({last.p + (e * i / ext_count) * last.t, last.t});

    CentreLine line;
    line.curve = reinterpolate(all, Precision::Confusion());
    if (line.curve.IsNull())
        throw Error(pipe_label(number) + ": cannot build one smooth curve along the path (points too close together?)");
    line.extension = e;
    double u = 0;
    for (std::size_t i = 1; i < all.size(); ++i) {
        u += norm(all[i].p - all[i - 1].p);
        if (i == static_cast<std::size_t>(ext_count)) line.path_first = u;
        if (i == all.size() - 1 - static_cast<std::size_t>(ext_count)) line.path_last = u;
    }
    detect_plane(all, host_extent(host), line);
    return line;
}

std::vector<Vec3> sample_path(const CentreLine& line, double spacing) {
    const double len = curve_length(line.curve, line.path_first, line.path_last);
    const int count = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    GeomAdaptor_Curve adaptor(line.curve, line.path_first, line.path_last);
    GCPnts_UniformAbscissa uniform(adaptor, count + 1, line.path_first, line.path_last);
    const bool by_length = uniform.IsDone() && uniform.NbPoints() == count + 1;
    std::vector<Vec3> out;
    out.reserve(static_cast<std::size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const double u = by_length ? uniform.Parameter(i + 1) : line.path_first + (line.path_last - line.path_first) * i / count;
        out.push_back(to_vec3(line.curve->Value(u).XYZ()));
    }
    return out;
}

double min_curvature_radius(const CentreLine& line) {
    if (auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(line.curve); !trimmed.IsNull()) {
        if (auto circle = Handle(Geom_Circle)::DownCast(trimmed->BasisCurve()); !circle.IsNull()) return circle->Radius();
        if (trimmed->BasisCurve()->IsKind(STANDARD_TYPE(Geom_Line))) return std::numeric_limits<double>::infinity();
    }
    int samples = 2000;
    if (auto bspline = Handle(Geom_BSplineCurve)::DownCast(line.curve); !bspline.IsNull())
        samples = std::max(samples, 16 * bspline->NbKnots());
    return sampled_min_radius(line.curve, line.path_first, line.path_last, samples);
}

}  // namespace tubemesh::geom
