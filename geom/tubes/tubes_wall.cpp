#include "geom/tubes/tubes_wall.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomLProp_SLProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

// Samples per edge when looking for where a generator line crosses it; each sign change is
// then refined by bisection, so this only has to separate distinct crossings.
constexpr int kCrossingSamples = 64;
// An interior edge at more than 60 degrees from the circumferential direction runs along the
// axis: a split around the axis (crossed by no generator line), not a split along it.
constexpr double kAlongAxisCos = 0.5;

double wrap(double x, double period) {
    if (period <= 0) return x;
    x = std::fmod(x, period);
    if (x > period / 2) x -= period;
    if (x <= -period / 2) x += period;
    return x;
}

// 0 when u is the more curved direction at (u, v), 1 for v, -1 when the surface is flat there.
int more_curved_direction(const Handle(Geom_Surface) & surface, double u, double v) {
    GeomLProp_SLProps props(surface, u, v, 2, 1e-9);
    if (!props.IsNormalDefined()) return -1;
    const gp_Vec n(props.Normal());
    const double ku = std::abs(props.D2U().Dot(n)) / props.D1U().SquareMagnitude();
    const double kv = std::abs(props.D2V().Dot(n)) / props.D1V().SquareMagnitude();
    if (!(std::max(ku, kv) > 0)) return -1;
    return ku >= kv ? 0 : 1;
}

// Outward unit normal of the solid at uv of a face (zero where the surface is singular).
gp_Vec outward_normal(const TopoDS_Face& face, const Handle(Geom_Surface) & surface, const gp_Pnt2d& uv) {
    gp_Pnt p;
    gp_Vec du, dv;
    surface->D1(uv.X(), uv.Y(), p, du, dv);
    gp_Vec n = du.Crossed(dv);
    if (n.Magnitude() < 1e-300) return gp_Vec(0, 0, 0);
    n.Normalize();
    return face.Orientation() == TopAbs_REVERSED ? -n : n;
}

}  // namespace

TubeWall::TubeWall(const TopologyIndex& index, TubeCandidate candidate)
    : index_(index), candidate_(std::move(candidate)) {
    for (int k = 0; k < 2; ++k) loops_[k] = std::make_unique<LoopCurve>(index_.model, candidate_.loops[k]);
    tolerance_ = std::max(1e-6 * loops_[0]->length(), 1e-12);
}

std::unique_ptr<TubeWall> TubeWall::build(const TopologyIndex& index, const TubeCandidate& candidate,
                                          const TubeOptions& options, std::string& why) {
    std::unique_ptr<TubeWall> wall(new TubeWall(index, candidate));
    why = wall->classify_faces(options);
    if (!why.empty()) return nullptr;
    return wall;
}

int TubeWall::face_index(int id) const {
    for (std::size_t k = 0; k < faces_.size(); ++k)
        if (faces_[k].id == id) return static_cast<int>(k);
    return -1;
}

std::string TubeWall::classify_faces(const TubeOptions& options) {
    const Model& model = index_.model;
    for (int id : candidate_.faces) {
        Face f;
        f.id = id;
        f.shape = face_of(model, id);
        const BRepAdaptor_Surface adaptor(f.shape);
        if (adaptor.GetType() == GeomAbs_Plane) return "face " + std::to_string(id) + " is planar";
        f.surface = BRep_Tool::Surface(f.shape);
        double u0, u1, v0, v1;
        BRepTools::UVBounds(f.shape, u0, u1, v0, v1);
        const bool uc = adaptor.IsUClosed(), vc = adaptor.IsVClosed();
        if (uc && vc) return "face " + std::to_string(id) + " closes on itself in both directions";
        if (uc || vc) {
            f.circ = uc ? 0 : 1;
            f.period = uc ? u1 - u0 : v1 - v0;
        } else {
            f.circ = more_curved_direction(f.surface, (u0 + u1) / 2, (v0 + v1) / 2);
            if (f.circ < 0) return "face " + std::to_string(id) + " is flat";
            f.period = 0;
        }
        f.c_lo = f.circ == 0 ? u0 : v0;
        f.c_hi = f.circ == 0 ? u1 : v1;
        faces_.push_back(std::move(f));
    }

    for (Face& f : faces_) {
        const std::string why = find_cuts(f, options);
        if (!why.empty()) return why;
    }
    return {};
}

// Sorts the face's edges into cuts (end-loop edges, and splits across the axis) and edges
// along the axis (seams, splits around the axis), checking the latter for creases.
std::string TubeWall::find_cuts(Face& f, const TubeOptions& options) {
    const Model& model = index_.model;
    std::set<int> seen;
    for (TopExp_Explorer it(f.shape, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge edge = TopoDS::Edge(it.Current());
        const int id = edge_id(model, edge);
        if (index_.degenerate[id] || !seen.insert(id).second) continue;
        int loop = -1;
        for (int k = 0; k < 2; ++k)
            for (const LoopEdge& e : candidate_.loops[k].edges)
                if (e.edge == id) loop = k;
        if (loop < 0 && BRep_Tool::IsClosed(edge, f.shape)) continue;  // a seam runs along the axis
        double t0, t1, e0, e1;
        Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, f.shape, t0, t1);
        if (pcurve.IsNull()) return "edge " + std::to_string(id) + " has no uv curve on face " + std::to_string(f.id);
        BRep_Tool::Range(edge, e0, e1);
        if (loop < 0) {
            // The edge's direction at its middle, from its uv curve (no parameter mapping needed).
            gp_Pnt2d uv;
            gp_Vec2d duv;
            pcurve->D1((t0 + t1) / 2, uv, duv);
            gp_Pnt p;
            gp_Vec du, dv;
            f.surface->D1(uv.X(), uv.Y(), p, du, dv);
            const gp_Vec tangent = du * duv.X() + dv * duv.Y();
            const gp_Vec around = f.circ == 0 ? du : dv;
            const double cosine = std::abs(tangent.Dot(around)) / (tangent.Magnitude() * around.Magnitude());
            if (cosine < kAlongAxisCos) {
                const std::string why = check_crease(f, edge, id, uv, options);
                if (!why.empty()) return why;
                continue;
            }
        }
        f.cuts.push_back({id, loop, edge, pcurve, t0, t1, e0, e1});
    }
    return {};
}

// A split along the axis must be smooth, or the group is a faceted slot, not a tube.
std::string TubeWall::check_crease(const Face& f, const TopoDS_Edge& edge, int id, const gp_Pnt2d& uv,
                                   const TubeOptions& options) const {
    for (int gid : index_.edge_faces[id]) {
        const int g = face_index(gid);
        if (g < 0 || gid == f.id) continue;
        const Face& other = faces_[g];
        double s0, s1;
        Handle(Geom2d_Curve) pc2 = BRep_Tool::CurveOnSurface(edge, other.shape, s0, s1);
        if (pc2.IsNull()) continue;
        // Both uv curves are read at the middle of their ranges: the same point of the edge.
        const gp_Vec n1 = outward_normal(f.shape, f.surface, uv);
        const gp_Vec n2 = outward_normal(other.shape, other.surface, pc2->Value((s0 + s1) / 2));
        if (n1.Magnitude() == 0 || n2.Magnitude() == 0) continue;
        const double deg = n1.Angle(n2) * 180 / std::numbers::pi;
        if (deg > options.max_crease_deg) {
            std::ostringstream s;
            s << kCreaseReason << deg << " degrees along edge " << id << " between faces " << f.id << " and " << gid;
            return s.str();
        }
    }
    return {};
}

std::vector<TubeWall::Crossing> TubeWall::crossings(const Face& face, double c) const {
    std::vector<Crossing> out;
    for (const Cut& cut : face.cuts) {
        const auto g = [&](double t) {
            const gp_Pnt2d uv = cut.pcurve->Value(t);
            return wrap((face.circ == 0 ? uv.X() : uv.Y()) - c, face.period);
        };
        const auto add = [&](double t) {
            const gp_Pnt2d uv = cut.pcurve->Value(t);
            const double te = cut.to_edge_param(t);
            out.push_back(
                {face.circ == 0 ? uv.Y() : uv.X(), cut.edge, cut.loop, te, BRepAdaptor_Curve(cut.shape).Value(te)});
        };
        double tp = cut.t0, gp = g(tp);
        if (gp == 0) add(tp);
        for (int i = 1; i <= kCrossingSamples; ++i) {
            const double t = cut.t0 + (cut.t1 - cut.t0) * i / kCrossingSamples;
            const double gv = g(t);
            if (gv == 0) {
                add(t);
            } else if (gp != 0 && (gp < 0) != (gv < 0) && (face.period == 0 || std::abs(gv - gp) < face.period / 2)) {
                double a = tp, b = t, ga = gp;
                for (int it = 0; it < 100 && b - a > 1e-15 * (std::abs(a) + std::abs(b) + 1); ++it) {
                    const double m = (a + b) / 2, gm = g(m);
                    if ((gm < 0) == (ga < 0)) {
                        a = m;
                        ga = gm;
                    } else {
                        b = m;
                    }
                }
                add((a + b) / 2);
            }
            tp = t;
            gp = gv;
        }
    }
    std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) { return a.axial < b.axial; });
    // A line through a vertex crosses both edges meeting there: one crossing.
    std::vector<Crossing> unique;
    for (const Crossing& x : out)
        if (unique.empty() || unique.back().p.Distance(x.p) > tolerance_) unique.push_back(x);
    return unique;
}

std::optional<TubeWall::Entry> TubeWall::enter(int edge, double t, int from_face) const {
    for (int gid : index_.edge_faces[edge]) {
        if (gid == from_face) continue;
        const int k = face_index(gid);
        if (k < 0) continue;
        for (const Cut& cut : faces_[k].cuts) {
            if (cut.edge != edge) continue;
            const gp_Pnt2d uv = cut.pcurve->Value(cut.to_uv_param(t));
            return Entry{k, faces_[k].circ == 0 ? uv.X() : uv.Y(), BRepAdaptor_Curve(cut.shape).Value(t)};
        }
    }
    return std::nullopt;
}

std::optional<Generator> TubeWall::walk(const LoopPoint& start) const {
    auto entry = enter(loops_[0]->edge_id(start.item), start.t, -1);
    if (!entry) return std::nullopt;
    entry->p = start.p;
    std::vector<GeneratorPiece> pieces;
    for (std::size_t step = 0; step < 2 * faces_.size() + 2; ++step) {
        const Face& f = faces_[entry->face];
        const std::vector<Crossing> xs = crossings(f, entry->c);
        // The crossings along the line alternate in, out, in, ...: the piece inside the face
        // runs from the entry to its partner.
        std::size_t i = 0;
        for (std::size_t k = 1; k < xs.size(); ++k)
            if (xs[k].p.Distance(entry->p) < xs[i].p.Distance(entry->p)) i = k;
        if (xs.size() < 2 || xs[i].p.Distance(entry->p) > 1e3 * tolerance_) return std::nullopt;
        const std::size_t j = i % 2 == 0 ? i + 1 : i - 1;
        if (j >= xs.size()) return std::nullopt;
        Handle(Geom_Curve) iso(f.circ == 0 ? f.surface->UIso(entry->c) : f.surface->VIso(entry->c));
        pieces.push_back({f.id, iso, xs[i].axial, xs[j].axial, 0});
        const Crossing& exit = xs[j];
        if (exit.loop == 1) {
            const auto end = loops_[1]->locate(exit.edge, exit.t);
            if (!end) return std::nullopt;
            return Generator(std::move(pieces), start, *end);
        }
        if (exit.loop == 0) return std::nullopt;  // turned back to E1
        auto next = enter(exit.edge, exit.t, f.id);
        if (!next) return std::nullopt;
        next->p = exit.p;
        entry = next;
    }
    return std::nullopt;
}

}  // namespace tubemesh::geom
