#include "geom/builders/block_builder.hpp"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <Precision.hxx>
#include <Geom_Circle.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/core/types.hpp"
#include "geom/builders/centre_line.hpp"
#include "geom/builders/clearance.hpp"
#include "geom/builders/host_geometry.hpp"
#include "geom/builders/pipe_sweep.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/solid_check.hpp"

namespace tubemesh::geom {

namespace {

constexpr double kPi = std::numbers::pi;

std::string label(int i) { return "pipe " + std::to_string(i + 1); }
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

TopoDS_Solid make_host(const HostSpec& host) {
    if (host.kind == HostSpec::Kind::Box) {
        if (!(host.size.x > 0 && host.size.y > 0 && host.size.z > 0))
            throw Error("the block's size must be positive in x, y and z");
        return BRepPrimAPI_MakeBox(host.size.x, host.size.y, host.size.z).Solid();
    }
    if (!(host.diameter > 0 && host.length > 0)) throw Error("the cylinder's diameter and length must be positive");
    return BRepPrimAPI_MakeCylinder(host.diameter / 2, host.length).Solid();
}

int host_face_count(const HostSpec& host) { return host.kind == HostSpec::Kind::Box ? 6 : 3; }

// The path must cross the boundary exactly twice (enter once, leave once): sampled along the
// whole extended curve, the signed distance changes sign twice, and both ends are outside by
// more than the radius (so the end caps are clear of the host).
void check_crossings(const CentreLine& line, const HostSpec& host, double radius, int i) {
    const double f = line.curve->FirstParameter(), l = line.curve->LastParameter();
    auto at = [&](double u) {
        const gp_Pnt p = line.curve->Value(u);
        return signed_boundary_distance(host, {p.X(), p.Y(), p.Z()});
    };
    if (at(f) > -radius)
        throw Error(label(i) + " does not start outside the block: its first point must lie on the boundary with the "
                    "path pointing into the block");
    if (at(l) > -radius)
        throw Error(label(i) + " does not end outside the block: its last point must lie on the boundary with the "
                    "path pointing out of the block");
    constexpr int kSamples = 4000;
    int changes = 0;
    bool inside = false;
    for (int k = 0; k <= kSamples; ++k) {
        const bool now = at(f + (l - f) * k / kSamples) > 0;
        if (k > 0 && now != inside) ++changes;
        inside = now;
    }
    if (changes == 0) throw Error(label(i) + " never enters the block");
    if (changes > 2) throw Error(label(i) + " leaves the block and enters it again: give it a path that stays inside");
}

// Length of the line through a and b inside the box, if both crossings lie inside one face each
// with the pipe's whole footprint (an ellipse with semi-axis r / cos(angle)) clear of the edges:
// then the removed volume is exactly pi r^2 times that length.
std::optional<double> line_length_in_box(const Vec3& a, const Vec3& b, const Vec3& size, double r) {
    const Vec3 d = unit(b - a);
    const double o[3] = {a.x, a.y, a.z}, v[3] = {d.x, d.y, d.z}, s[3] = {size.x, size.y, size.z};
    double t0 = -1e300, t1 = 1e300;
    int axis0 = -1, axis1 = -1;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(v[k]) < 1e-15) {
            if (o[k] < 0 || o[k] > s[k]) return std::nullopt;
            continue;
        }
        double lo = (0 - o[k]) / v[k], hi = (s[k] - o[k]) / v[k];
        if (lo > hi) std::swap(lo, hi);
        if (lo > t0) t0 = lo, axis0 = k;
        if (hi < t1) t1 = hi, axis1 = k;
    }
    if (t1 <= t0 || axis0 < 0 || axis1 < 0) return std::nullopt;
    for (auto [t, axis] : {std::pair{t0, axis0}, std::pair{t1, axis1}}) {
        const double footprint = r / std::abs(v[axis]);
        for (int k = 0; k < 3; ++k) {
            if (k == axis) continue;
            const double x = o[k] + t * v[k];
            if (x < footprint || x > s[k] - footprint) return std::nullopt;
        }
    }
    return t1 - t0;
}

// An arc removes a torus section, pi r^2 R theta (Pappus), when both end planes contain the arc's
// axis: each end point on a box face whose plane passes through the centre, normal
// perpendicular to the axis, the end circle clear of the face's edges.
std::optional<double> arc_volume_in_box(const CentreLine& line, const HostSpec& host, double r) {
    auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(line.curve);
    if (trimmed.IsNull()) return std::nullopt;
    auto circle = Handle(Geom_Circle)::DownCast(trimmed->BasisCurve());
    if (circle.IsNull()) return std::nullopt;
    const double tol = 1e-9 * host_extent(host);
    const gp_Pnt c = circle->Location();
    const gp_Dir axis = circle->Axis().Direction();
    const Vec3 centre{c.X(), c.Y(), c.Z()}, ax{axis.X(), axis.Y(), axis.Z()};
    for (double u : {line.path_first, line.path_last}) {
        const gp_Pnt p = line.curve->Value(u);
        const Vec3 end{p.X(), p.Y(), p.Z()};
        const std::optional<Vec3> n = boundary_normal(host, end, tol);
        if (!n) return std::nullopt;
        if (std::abs(dot(*n, centre - end)) > tol || std::abs(dot(*n, ax)) > 1e-9) return std::nullopt;
        // The end circle (radius r, in the face plane) must stay inside the face.
        const double coords[3] = {end.x, end.y, end.z}, sizes[3] = {host.size.x, host.size.y, host.size.z};
        const double normal[3] = {n->x, n->y, n->z};
        for (int k = 0; k < 3; ++k)
            if (std::abs(normal[k]) < 0.5 && (coords[k] < r || coords[k] > sizes[k] - r)) return std::nullopt;
    }
    return kPi * r * r * circle->Radius() * (line.path_last - line.path_first);
}

std::optional<double> removed_volume(const PipeSpec& pipe, const CentreLine& line, const HostSpec& host) {
    if (host.kind != HostSpec::Kind::Box || !line.exact) return std::nullopt;
    const double r = pipe.diameter / 2;
    if (pipe.kind == PathKind::Arc) return arc_volume_in_box(line, host, r);
    const std::optional<double> len = line_length_in_box(pipe.points.front(), pipe.points.back(), host.size, r);
    if (!len) return std::nullopt;
    return kPi * r * r * *len;
}

const double kSmallestLength = 1000 * Precision::Confusion();

void check_clearances(const BlockSpec& spec, const std::vector<CentreLine>& lines) {
    std::vector<PipeSamples> samples;
    double min_d = Clearance::kNone;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const double d = spec.pipes[i].diameter;
        min_d = std::min(min_d, d);
        samples.push_back({sample_path(lines[i], d / 2), d / 2});
    }
    const Clearance c = measure_clearance(samples, spec.host, 2 * min_d);
    if (c.pipe_gap < 0.5 * min_d)
        throw Error(label(c.pipe_a) + " and " + label(c.pipe_b) + " come within " + num(std::max(c.pipe_gap, 0.0)) +
                    " of each other (wall to wall): keep pipes at least half a diameter apart");
    if (c.self_gap < 0.5 * min_d)
        throw Error(label(c.self_pipe) + " comes within " + num(std::max(c.self_gap, 0.0)) +
                    " of itself (wall to wall): open up its bends");
    if (c.boundary_gap < 0.1 * min_d)
        throw Error(label(c.boundary_pipe) + " comes within " + num(std::max(c.boundary_gap, 0.0)) +
                    " of the block's boundary away from its ends: move it inwards");
}

}  // namespace

BuiltBlock build_block(const BlockSpec& spec) {
    // OpenCASCADE's tolerances are absolute (1e-7): below a thousand times that, booleans and
    // sweeps fail in ways that say nothing about the cause.
    const double smallest = kSmallestLength;
    for (std::size_t i = 0; i < spec.pipes.size(); ++i)
        if (spec.pipes[i].diameter > 0 && spec.pipes[i].diameter < smallest)
            throw Error(label(static_cast<int>(i)) + ": its diameter " + num(spec.pipes[i].diameter) + " is below " +
                        num(smallest) + ", too small for OpenCASCADE's fixed tolerance of " +
                        num(Precision::Confusion()) + ": give the spec in a smaller unit (micrometres, say)");
    try {
        const TopoDS_Solid host = make_host(spec.host);

        std::vector<CentreLine> lines;
        for (std::size_t i = 0; i < spec.pipes.size(); ++i) {
            const int n = static_cast<int>(i);
            lines.push_back(make_centre_line(spec.pipes[i], spec.host, n + 1));
            const double r = spec.pipes[i].diameter / 2;
            if (!spec.pipes[i].blind) check_crossings(lines.back(), spec.host, r, n);
            const double rho = min_curvature_radius(lines.back());
            if (rho < 1.5 * r)
                throw Error(label(n) + " bends too tightly: its smallest radius of curvature is " + num(rho) +
                            " for a pipe radius of " + num(r) + " (keep it above " + num(1.5 * r) + ")");
        }
        if (spec.check_clearance) check_clearances(spec, lines);

        // All pipes in one compound, the boolean's single tool: OpenCASCADE then never
        // intersects one pipe with another (sub-shapes of one argument are taken as disjoint,
        // which check_clearances has made sure of). As separate tools, those pairwise tests
        // took most of the cut; one cut is also independent of any order.
        // Unchecked pipes may cross: then each is a tool of its own.
        BRep_Builder builder;
        TopoDS_Compound pipes;
        builder.MakeCompound(pipes);
        TopTools_ListOfShape arguments, tools;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const TopoDS_Solid pipe = sweep_pipe(lines[i], spec.pipes[i].diameter, static_cast<int>(i) + 1);
            if (spec.check_clearance)
                builder.Add(pipes, pipe);
            else
                tools.Append(pipe);
        }
        arguments.Append(host);
        if (spec.check_clearance) tools.Append(pipes);

        std::vector<TopoDS_Solid> solids;
        if (spec.pipes.empty()) {
            solids.push_back(host);
        } else {
            BRepAlgoAPI_Cut cut;
            cut.SetArguments(arguments);
            cut.SetTools(tools);
            cut.SetUseOBB(Standard_True);  // oriented boxes: fewer false overlaps between curved pipes and faces
            cut.Build();
            if (!cut.IsDone() || cut.HasErrors())
                throw Error("cutting the pipes from the block failed in OpenCASCADE's boolean: check that the pipes do "
                            "not touch each other or the block's edges");
            for (TopExp_Explorer it(cut.Shape(), TopAbs_SOLID); it.More(); it.Next())
                solids.push_back(TopoDS::Solid(it.Current()));
        }
        if (solids.size() != 1)
            throw Error("cutting the pipes split the block into " + std::to_string(solids.size()) +
                        " pieces: a pipe cuts the block in two");
        const std::string problems = validity_problems(solids.front());
        if (!problems.empty()) throw Error("the block with its pipes is not a valid solid (" + problems + ")");

        int faces = 0;
        for (TopExp_Explorer it(solids.front(), TopAbs_FACE); it.More(); it.Next()) ++faces;
        const int expected_faces = host_face_count(spec.host) + static_cast<int>(spec.pipes.size());
        const bool plain = spec.check_clearance &&
                           std::none_of(spec.pipes.begin(), spec.pipes.end(), [](const PipeSpec& p) { return p.blind; });
        if (plain && faces != expected_faces)
            throw Error("the block with its pipes has " + std::to_string(faces) + " faces where " +
                        std::to_string(expected_faces) +
                        " were expected (the host's and one wall per pipe): a pipe ends on a block edge or on another pipe");

        BlockInfo info;
        info.name = spec.name;
        info.length_unit = spec.length_unit;
        info.pipe_count = static_cast<int>(spec.pipes.size());
        for (const PipeSpec& p : spec.pipes) info.pipe_diameters.push_back(p.diameter);
        info.host_volume = host_volume(spec.host);
        double removed = 0;
        bool analytic = plain;  // crossing or blind pipes have no closed form here
        for (std::size_t i = 0; i < lines.size() && analytic; ++i) {
            const std::optional<double> v = removed_volume(spec.pipes[i], lines[i], spec.host);
            analytic = v.has_value();
            removed += v.value_or(0);
        }
        if (analytic) info.expected_volume = info.host_volume - removed;

        ImportReport report;
        report.source = "builder: " + spec.name;
        report.format = "built";
        report.name = spec.name;
        report.length_unit = spec.length_unit;
        Model model = make_model(solids.front(), std::move(report));
        info.volume = model.volume();
        return {std::move(model), std::move(info)};
    } catch (const Standard_Failure& e) {
        throw Error("building '" + spec.name + "' failed in OpenCASCADE: " + e.GetMessageString());
    }
}

}  // namespace tubemesh::geom
