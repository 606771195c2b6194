#include "geom/sizing/sizing_distances.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Torus.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "engine/core/vec3_ops.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

// Closest distance between segments p0-p1 and q0-q1, degenerate segments included.
double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    return std::sqrt(segment_segment_distance2(p0, p1, q0, q1));
}

// Bounding boxes of runs of segments, so most segment pairs are never looked at.
struct Chunk {
    std::size_t first, last;  // segment indices [first, last)
    Vec3 lo, hi;
};

constexpr std::size_t kChunk = 16;

std::vector<Chunk> chunks(const std::vector<Vec3>& line) {
    std::vector<Chunk> out;
    const std::size_t segments = line.size() > 1 ? line.size() - 1 : 1;
    for (std::size_t first = 0; first < segments; first += kChunk) {
        Chunk c{first, std::min(first + kChunk, segments), line[first], line[first]};
        for (std::size_t i = first; i <= std::min(c.last, line.size() - 1); ++i) {
            c.lo = {std::min(c.lo.x, line[i].x), std::min(c.lo.y, line[i].y), std::min(c.lo.z, line[i].z)};
            c.hi = {std::max(c.hi.x, line[i].x), std::max(c.hi.y, line[i].y), std::max(c.hi.z, line[i].z)};
        }
        out.push_back(c);
    }
    return out;
}

double box_distance(const Chunk& a, const Chunk& b) {
    const double dx = std::max({0.0, a.lo.x - b.hi.x, b.lo.x - a.hi.x});
    const double dy = std::max({0.0, a.lo.y - b.hi.y, b.lo.y - a.hi.y});
    const double dz = std::max({0.0, a.lo.z - b.hi.z, b.lo.z - a.hi.z});
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Douglas-Peucker: the points of `line` to keep so that no dropped point lies farther than
// `tolerance` from the kept polyline, which then lies within `tolerance` of the original, so
// every distance to it moves by at most that. Ends always kept; deterministic.
std::vector<Vec3> without_straight_runs(const std::vector<Vec3>& line, double tolerance) {
    if (line.size() < 3) return line;
    std::vector<char> keep(line.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<std::array<std::size_t, 2>> runs{{0, line.size() - 1}};
    while (!runs.empty()) {
        const auto [a, b] = runs.back();
        runs.pop_back();
        double worst = -1;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i) {
            const double d = segment_distance(line[i], line[i], line[a], line[b]);  // point to chord
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst <= tolerance) continue;
        keep[at] = 1;
        runs.push_back({a, at});
        runs.push_back({at, b});
    }
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < line.size(); ++i)
        if (keep[i]) out.push_back(line[i]);
    return out;
}

// The centre line as an OCCT shape: a polygon wire, or a vertex for a one-point line.
TopoDS_Shape polyline_shape(const std::vector<Vec3>& line) {
    if (line.size() == 1) return BRepBuilderAPI_MakeVertex(gp_Pnt(line[0].x, line[0].y, line[0].z)).Shape();
    BRepBuilderAPI_MakePolygon polygon;
    for (const Vec3& p : line) polygon.Add(gp_Pnt(p.x, p.y, p.z));
    return polygon.Shape();
}

// How far the wire given to BRepExtrema may stray from the centre line, over the tube's
// radius: rounding level, so a straight run of a pipe (its samples are about a diameter apart)
// becomes one edge and a bend keeps every point. Each vertex costs BRepExtrema a point
// classification on the face (bench/results/tuning-notes.md).
constexpr double kWireTolerance = 1e-9;

}  // namespace

double polyline_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double best = std::numeric_limits<double>::infinity();
    const auto ca = chunks(a), cb = chunks(b);
    const auto end = [](const std::vector<Vec3>& l, std::size_t i) { return l[std::min(i + 1, l.size() - 1)]; };
    for (const Chunk& x : ca)
        for (const Chunk& y : cb) {
            if (box_distance(x, y) >= best) continue;
            for (std::size_t i = x.first; i < x.last; ++i)
                for (std::size_t j = y.first; j < y.last; ++j)
                    best = std::min(best, segment_distance(a[i], end(a, i), b[j], end(b, j)));
        }
    return best;
}

BoundingBox non_wall_box(const Model& model, const std::vector<TubeInfo>& tubes) {
    std::set<int> walls;
    for (const TubeInfo& t : tubes) walls.insert(t.faces.begin(), t.faces.end());
    Bnd_Box box;
    for (int f = 1; f <= model.face_count(); ++f)
        if (!walls.count(f)) BRepBndLib::Add(face_of(model, f), box);
    if (box.IsVoid()) BRepBndLib::Add(solid_of(model), box);
    BoundingBox b;
    if (!box.IsVoid()) box.Get(b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z);
    return b;
}

double box_diagonal(const Model& model, const std::vector<TubeInfo>& tubes) {
    const BoundingBox b = non_wall_box(model, tubes);
    const double dx = b.max.x - b.min.x, dy = b.max.y - b.min.y, dz = b.max.z - b.min.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

Clearances measure_clearances(const Model& model, const std::vector<TubeInfo>& tubes) {
    Clearances c;
    for (std::size_t i = 0; i < tubes.size(); ++i)
        for (std::size_t j = i + 1; j < tubes.size(); ++j) {
            const double d = polyline_distance(tubes[i].centre_line, tubes[j].centre_line) - tubes[i].radius_max -
                             tubes[j].radius_max;
            if (d < c.dc) {
                c.dc = d;
                c.dc_tube_a = static_cast<int>(i);
                c.dc_tube_b = static_cast<int>(j);
            }
        }

    std::set<int> walls;
    for (const TubeInfo& t : tubes) walls.insert(t.faces.begin(), t.faces.end());
    // Each centre line in pieces of kChunk segments, each its own wire with its own box: the
    // distance from a face to the line is the least over the pieces, and a piece whose box is
    // no nearer than the best distance so far cannot lower it. Nearest boxes first, so one or
    // two BRepExtrema calls on short wires do what one call on the whole line did (a gently
    // curved pipe keeps all its samples).
    struct Piece {
        TopoDS_Shape wire;
        Bnd_Box box;
    };
    std::vector<std::vector<Piece>> pieces(tubes.size());
    for (std::size_t i = 0; i < tubes.size(); ++i) {
        const std::vector<Vec3> line = without_straight_runs(tubes[i].centre_line, kWireTolerance * tubes[i].radius_max);
        for (const Chunk& ch : chunks(line)) {
            const std::size_t last = std::min(ch.last, line.size() - 1);
            Piece piece;
            piece.wire = polyline_shape({line.begin() + static_cast<std::ptrdiff_t>(ch.first),
                                         line.begin() + static_cast<std::ptrdiff_t>(last) + 1});
            BRepBndLib::Add(piece.wire, piece.box);
            pieces[i].push_back(std::move(piece));
        }
    }
    std::vector<std::pair<double, std::size_t>> order;
    for (int f = 1; f <= model.face_count(); ++f) {
        if (walls.count(f)) continue;
        const TopoDS_Face face = face_of(model, f);
        Bnd_Box face_box;
        BRepBndLib::Add(face, face_box);  // enlarged by tolerances: never farther than the face
        for (std::size_t i = 0; i < tubes.size(); ++i) {
            if (tubes[i].hosts[0] == f || tubes[i].hosts[1] == f) continue;
            const double r = tubes[i].radius_max;
            order.clear();
            for (std::size_t k = 0; k < pieces[i].size(); ++k)
                order.emplace_back(face_box.Distance(pieces[i][k].box), k);
            std::sort(order.begin(), order.end());
            for (const auto& [box_gap, k] : order) {
                // The boxes are enlarged by the shapes' tolerances (about 1e-7), so a piece as far
                // as the best one so far (a pipe parallel to a face: every piece ties) would never
                // be skipped; one within those tolerances of it cannot matter.
                const double slack = face_box.GetGap() + pieces[i][k].box.GetGap();
                if (box_gap + slack - r >= c.dcb) break;
                BRepExtrema_DistShapeShape dist(face, pieces[i][k].wire);
                if (!dist.IsDone() || dist.NbSolution() == 0) continue;
                if (dist.Value() - r < c.dcb) {
                    c.dcb = dist.Value() - r;
                    c.dcb_tube = static_cast<int>(i);
                    c.dcb_face = f;
                }
            }
        }
    }
    return c;
}

std::vector<HoleGroup> hole_groups(const Model& model, const TubeSearch& tubes, double size) {
    std::vector<HoleGroup> out;
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    std::vector<Bnd_Box> boxes;
    for (const TubeRejection& rejected : tubes.rejected) {
        HoleGroup h;
        h.faces = rejected.faces;
        h.radius = rejected.radius > 0 ? rejected.radius : std::numeric_limits<double>::infinity();
        for (int f : rejected.radius > 0 ? std::vector<int>{} : rejected.faces) {
            const BRepAdaptor_Surface surface(face_of(model, f));
            if (surface.GetType() == GeomAbs_Cylinder)
                h.radius = std::min(h.radius, surface.Cylinder().Radius());
            else if (surface.GetType() == GeomAbs_Torus)
                h.radius = std::min(h.radius, surface.Torus().MinorRadius());
        }
        if (!std::isfinite(h.radius)) continue;  // no face with a known radius: nothing to judge by
        if (boxes.empty()) {
            TopExp::MapShapesAndAncestors(solid_of(model), TopAbs_EDGE, TopAbs_FACE, edge_faces);
            boxes.resize(static_cast<std::size_t>(model.face_count()) + 1);
            for (int g = 1; g <= model.face_count(); ++g) BRepBndLib::Add(face_of(model, g), boxes[g]);
        }
        // The group's own faces and those it shares an edge with (its hosts) meet it.
        std::set<int> touching(rejected.faces.begin(), rejected.faces.end());
        for (int f : rejected.faces)
            for (TopExp_Explorer e(face_of(model, f), TopAbs_EDGE); e.More(); e.Next()) {
                const int k = edge_faces.FindIndex(e.Current());
                if (k == 0) continue;
                for (const TopoDS_Shape& g : edge_faces(k)) touching.insert(model.impl().faces.FindIndex(g));
            }
        const double within = std::max(h.radius, size);
        for (int g = 1; g <= model.face_count(); ++g) {
            if (touching.count(g)) continue;
            bool near = false;
            for (int f : rejected.faces) near = near || boxes[f].Distance(boxes[g]) <= within;
            if (near) h.near_faces.push_back(g);
        }
        out.push_back(std::move(h));
    }
    return out;
}

std::vector<HoleClearance> measure_hole_clearances(const Model& model, const std::vector<HoleGroup>& holes) {
    std::vector<HoleClearance> out;
    for (const HoleGroup& group : holes) {
        HoleClearance h{group.faces, group.radius};
        for (int f : group.faces)
            for (int g : group.near_faces) {
                BRepExtrema_DistShapeShape dist(face_of(model, f), face_of(model, g));
                if (dist.IsDone() && dist.NbSolution() > 0 && dist.Value() < h.distance) {
                    h.distance = dist.Value();
                    h.face = g;
                }
            }
        if (h.face > 0) out.push_back(std::move(h));
    }
    return out;
}

}  // namespace tubemesh::geom
