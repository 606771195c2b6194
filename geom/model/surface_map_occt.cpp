#include "geom/model/surface_map_occt.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

Vec3 to_vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

// Upper bound on grid samples per direction for unhinted projections (the grid has at most
// about this many points in all when the face is square).
constexpr int kGridPoints = 32;

// Folds a periodic parameter back next to the face: into [lo, lo + period) for a face that
// wraps, else to the twin nearest the face's range.
double normalise(double x, const ParamRange& r) {
    if (r.period <= 0) return x;
    if (r.closed) {
        double y = std::fmod(x - r.lo, r.period);
        if (y < 0) y += r.period;
        return r.lo + y;
    }
    const double mid = (r.lo + r.hi) / 2;
    return x - r.period * std::round((x - mid) / r.period);
}

Handle(Geom_Surface) untrimmed(Handle(Geom_Surface) s) {
    while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = trimmed->BasisSurface();
    return s;
}

class OcctSurfaceMap final : public SurfaceMap {
public:
    OcctSurfaceMap(const Model& model, int face_id);

    index_t face() const override { return static_cast<index_t>(id_); }
    ParamRange u_range() const override { return u_; }
    ParamRange v_range() const override { return v_; }
    bool reversed() const override { return reversed_; }
    Vec3 point(Uv uv) const override;
    SurfaceDerivatives derivatives(Uv uv) const override;
    Projection project(const Vec3& p, std::optional<Uv> hint) const override;
    Uv edge_uv(EdgeUse use, double t) const override;
    std::vector<TrimLoop> trimming_loops(double max_step) const override;

private:
    struct Use {
        EdgeUse use;
        Handle(Geom2d_Curve) pcurve;  // the master copy; threads evaluate their own
        double t0, t1;                // the uv curve's range
        double e0, e1;                // the edge's own range, which edge_uv's t refers to
        double length;
    };
    // One thread's private copies of everything with mutable state inside.
    struct Local {
        Handle(GeomAdaptor_Surface) adaptor;
        Handle(ShapeAnalysis_Surface) projector;
        std::vector<Handle(Geom2d_Curve)> pcurves;  // parallel to uses_
        // Samples over the face's uv box: a projection without a hint starts from the nearest,
        // ~50x faster than ShapeAnalysis_Surface's global search.
        std::vector<gp_Pnt> grid_points;
        std::vector<gp_Pnt2d> grid_uv;
        double extent = 0;  // the grid's bounding-box diagonal: the face's size
    };
    Local make_local() const;
    const Use& find_use(EdgeUse use, std::size_t& index) const;
    gp_Pnt2d polish(const Local& local, const gp_Pnt& p, gp_Pnt2d uv) const;
    bool is_foot(const Local& local, const gp_Pnt& p, const gp_Pnt2d& uv) const;

    int id_;
    bool reversed_;
    Handle(Geom_Surface) surface_;
    Handle(Geom_Surface) basis_;  // untrimmed, for projection: trimmed pieces project anywhere
    ParamRange u_, v_;
    std::vector<Use> uses_;
    std::vector<std::vector<std::size_t>> wires_;  // indices into uses_; outer wire first
    mutable tbb::enumerable_thread_specific<Local> locals_;
};

OcctSurfaceMap::OcctSurfaceMap(const Model& model, int face_id)
    : id_(face_id), locals_([this] { return make_local(); }) {
    if (face_id < 1 || face_id > model.face_count())
        throw Error("face " + std::to_string(face_id) + " is not a face of the model (it has " +
                    std::to_string(model.face_count()) + ")");
    const TopoDS_Face oriented = face_of(model, face_id);
    reversed_ = oriented.Orientation() == TopAbs_REVERSED;
    const TopoDS_Face face = TopoDS::Face(oriented.Oriented(TopAbs_FORWARD));
    surface_ = BRep_Tool::Surface(face);
    basis_ = untrimmed(surface_);

    const BRepAdaptor_Surface adaptor(face);
    BRepTools::UVBounds(face, u_.lo, u_.hi, v_.lo, v_.hi);
    u_.closed = adaptor.IsUClosed();
    v_.closed = adaptor.IsVClosed();
    // A closed B-spline need not be flagged periodic (STEP files often clamp it); its twins at
    // lo and hi are still the same point, so the span serves as the period.
    u_.period = basis_->IsUPeriodic() ? basis_->UPeriod() : (u_.closed ? u_.hi - u_.lo : 0);
    v_.period = basis_->IsVPeriodic() ? basis_->VPeriod() : (v_.closed ? v_.hi - v_.lo : 0);

    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    std::vector<TopoDS_Wire> wires{outer};
    for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next())
        if (!it.Current().IsSame(outer)) wires.push_back(TopoDS::Wire(it.Current()));
    for (const TopoDS_Wire& wire : wires) {
        if (wire.IsNull()) continue;
        std::vector<std::size_t> loop;
        for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
            // Degenerate edges (a cone's apex, a sphere's pole) stay: they have no 3D extent but
            // are a stretch of the uv boundary all the same.
            const TopoDS_Edge& edge = it.Current();
            Use use;
            use.use = {static_cast<index_t>(edge_id(model, edge)), edge.Orientation() != TopAbs_REVERSED};
            // The edge's orientation picks the uv curve: on a seam the two uses differ.
            use.pcurve = BRep_Tool::CurveOnSurface(edge, face, use.t0, use.t1);
            if (use.pcurve.IsNull())
                throw Error("edge " + std::to_string(use.use.edge) + " has no uv curve on face " +
                            std::to_string(face_id) + ": the model needs healing");
            BRep_Tool::Range(edge, use.e0, use.e1);
            use.length = BRep_Tool::Degenerated(edge) ? 0.0 : GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge));
            loop.push_back(uses_.size());
            uses_.push_back(use);
        }
        wires_.push_back(std::move(loop));
    }
}

OcctSurfaceMap::Local OcctSurfaceMap::make_local() const {
    Local local;
    const Handle(Geom_Surface) surface = Handle(Geom_Surface)::DownCast(surface_->Copy());
    const Handle(Geom_Surface) basis = Handle(Geom_Surface)::DownCast(basis_->Copy());
    local.adaptor = new GeomAdaptor_Surface(surface);
    local.projector = new ShapeAnalysis_Surface(basis);
    for (const Use& use : uses_) local.pcurves.push_back(Handle(Geom2d_Curve)::DownCast(use.pcurve->Copy()));
    // Grid resolution from the face's extent in each direction, so a long thin tube wall gets
    // samples along its length rather than a square grid.
    const auto extent = [&](bool along_u) {
        double len = 0;
        gp_Pnt prev;
        for (int i = 0; i <= 16; ++i) {
            const double f = i / 16.0;
            const gp_Pnt p = along_u ? local.adaptor->Value(u_.lo + f * (u_.hi - u_.lo), (v_.lo + v_.hi) / 2)
                                     : local.adaptor->Value((u_.lo + u_.hi) / 2, v_.lo + f * (v_.hi - v_.lo));
            if (i > 0) len += p.Distance(prev);
            prev = p;
        }
        return len;
    };
    const double lu = extent(true), lv = extent(false);
    const double h = std::max(std::sqrt(lu * lv / kGridPoints), std::max(lu, lv) / kGridPoints);
    const int nu = std::clamp(static_cast<int>(lu / std::max(h, 1e-300)), 4, kGridPoints);
    const int nv = std::clamp(static_cast<int>(lv / std::max(h, 1e-300)), 4, kGridPoints);
    for (int i = 0; i <= nu; ++i)
        for (int j = 0; j <= nv; ++j) {
            const gp_Pnt2d uv(u_.lo + (u_.hi - u_.lo) * i / nu, v_.lo + (v_.hi - v_.lo) * j / nv);
            local.grid_uv.push_back(uv);
            local.grid_points.push_back(local.adaptor->Value(uv.X(), uv.Y()));
        }
    gp_XYZ lo = local.grid_points.front().XYZ(), hi = lo;
    for (const gp_Pnt& p : local.grid_points) {
        lo.SetCoord(std::min(lo.X(), p.X()), std::min(lo.Y(), p.Y()), std::min(lo.Z(), p.Z()));
        hi.SetCoord(std::max(hi.X(), p.X()), std::max(hi.Y(), p.Y()), std::max(hi.Z(), p.Z()));
    }
    local.extent = (hi - lo).Modulus();
    return local;
}

Vec3 OcctSurfaceMap::point(Uv uv) const { return to_vec(locals_.local().adaptor->Value(uv.u, uv.v).XYZ()); }

SurfaceDerivatives OcctSurfaceMap::derivatives(Uv uv) const {
    gp_Pnt p;
    gp_Vec du, dv;
    locals_.local().adaptor->D1(uv.u, uv.v, p, du, dv);
    return {to_vec(p.XYZ()), to_vec(du.XYZ()), to_vec(dv.XYZ())};
}

// Gauss-Newton towards the foot point, each step kept only if it gets closer. From a nearby
// start (a hint, the nearest grid sample) this converges in a few steps; ShapeAnalysis_Surface
// is ~50x slower and stops at its own precision.
gp_Pnt2d OcctSurfaceMap::polish(const Local& local, const gp_Pnt& p, gp_Pnt2d uv) const {
    gp_Pnt s;
    gp_Vec du, dv;
    local.adaptor->D1(uv.X(), uv.Y(), s, du, dv);
    double best = s.SquareDistance(p);
    for (int it = 0; it < 16 && best > 0; ++it) {
        const gp_Vec r(s, p);
        const double a = du.Dot(du), b = du.Dot(dv), c = dv.Dot(dv);
        const double det = a * c - b * b;
        if (!(std::abs(det) > 1e-300)) break;
        const double ru = du.Dot(r), rv = dv.Dot(r);
        const gp_Pnt2d next(uv.X() + (c * ru - b * rv) / det, uv.Y() + (a * rv - b * ru) / det);
        gp_Pnt sn;
        gp_Vec dun, dvn;
        local.adaptor->D1(next.X(), next.Y(), sn, dun, dvn);
        const double d = sn.SquareDistance(p);
        if (!(d < best)) break;
        uv = next;
        s = sn;
        du = dun;
        dv = dvn;
        best = d;
    }
    return uv;
}

// True when uv is a foot point of p: the offset from the surface has no tangential part.
bool OcctSurfaceMap::is_foot(const Local& local, const gp_Pnt& p, const gp_Pnt2d& uv) const {
    gp_Pnt s;
    gp_Vec du, dv;
    local.adaptor->D1(uv.X(), uv.Y(), s, du, dv);
    const gp_Vec r(s, p);
    // Gauss-Newton stops where rounding in the surface's evaluation hides any further gain,
    // ~sqrt(distance * 1e-16): far above 1e-7 of a small distance, far below 1e-9 of the face.
    const double tolerance = 1e-7 * r.Magnitude() + 1e-9 * local.extent;
    return std::abs(r.Dot(du)) <= tolerance * du.Magnitude() && std::abs(r.Dot(dv)) <= tolerance * dv.Magnitude();
}

Projection OcctSurfaceMap::project(const Vec3& p, std::optional<Uv> hint) const {
    Local& local = locals_.local();
    const gp_Pnt target(p.x, p.y, p.z);
    constexpr double kPrecision = 1e-9;
    std::size_t best = 0;
    for (std::size_t i = 1; i < local.grid_points.size(); ++i)
        if (local.grid_points[i].SquareDistance(target) < local.grid_points[best].SquareDistance(target)) best = i;
    gp_Pnt2d uv = polish(local, target, hint ? gp_Pnt2d(hint->u, hint->v) : local.grid_uv[best]);
    // A poor hint can lead to the far side of a tube, which is stationary too (a maximum): a
    // foot point farther than the nearest grid sample is not the foot point.
    if (hint && local.adaptor->Value(uv.X(), uv.Y()).Distance(target) > local.grid_points[best].Distance(target))
        uv = polish(local, target, local.grid_uv[best]);
    // Far from the surface (near a tube's axis) Gauss-Newton need not converge: then
    // ShapeAnalysis_Surface's global search decides.
    if (!is_foot(local, target, uv)) uv = polish(local, target, local.projector->ValueOfUV(target, kPrecision));
    if (!std::isfinite(uv.X()) || !std::isfinite(uv.Y())) return {};
    Projection out;
    out.uv = {normalise(uv.X(), u_), normalise(uv.Y(), v_)};
    out.point = point(out.uv);
    const double dx = out.point.x - p.x, dy = out.point.y - p.y, dz = out.point.z - p.z;
    out.distance = std::sqrt(dx * dx + dy * dy + dz * dz);
    out.ok = std::isfinite(out.distance);
    return out;
}

const OcctSurfaceMap::Use& OcctSurfaceMap::find_use(EdgeUse use, std::size_t& index) const {
    // The exact use first (a seam has two); any use of the edge otherwise, since a non-seam
    // edge has one uv curve whichever way it is run.
    for (std::size_t k = 0; k < uses_.size(); ++k)
        if (uses_[k].use.edge == use.edge && uses_[k].use.forward == use.forward) return uses_[index = k];
    for (std::size_t k = 0; k < uses_.size(); ++k)
        if (uses_[k].use.edge == use.edge) return uses_[index = k];
    throw Error("edge " + std::to_string(use.edge) + " is not on face " + std::to_string(id_));
}

Uv OcctSurfaceMap::edge_uv(EdgeUse use, double t) const {
    std::size_t k = 0;
    const Use& u = find_use(use, k);
    // Not every edge is "same range" (ShapeUpgrade_ShapeDivideClosed leaves uv curves one
    // period away from the 3D curve): map the edge's parameter onto the uv curve's range.
    const double tp = u.e1 == u.e0 ? t : u.t0 + (t - u.e0) * (u.t1 - u.t0) / (u.e1 - u.e0);
    const gp_Pnt2d uv = locals_.local().pcurves[k]->Value(tp);
    return {uv.X(), uv.Y()};
}

std::vector<TrimLoop> OcctSurfaceMap::trimming_loops(double max_step) const {
    const Local& local = locals_.local();
    std::vector<TrimLoop> loops;
    for (const auto& wire : wires_) {
        TrimLoop loop;
        for (std::size_t k : wire) {
            const Use& use = uses_[k];
            const int n = std::max(4, max_step > 0 ? static_cast<int>(std::ceil(use.length / max_step)) : 4);
            loop.edges.push_back(use.use);
            loop.edge_begin.push_back(loop.uv.size());
            // The next use starts where this one ends: leave the end point to it.
            for (int i = 0; i < n; ++i) {
                const double f = static_cast<double>(i) / n;
                const double t = use.use.forward ? use.t0 + f * (use.t1 - use.t0) : use.t1 - f * (use.t1 - use.t0);
                const gp_Pnt2d uv = local.pcurves[k]->Value(t);
                loop.uv.push_back({uv.X(), uv.Y()});
            }
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace

std::unique_ptr<SurfaceMap> make_surface_map(const Model& model, int face_id) {
    return std::make_unique<OcctSurfaceMap>(model, face_id);
}

std::vector<std::unique_ptr<SurfaceMap>> make_surface_maps(const Model& model) {
    std::vector<std::unique_ptr<SurfaceMap>> maps;
    for (int f = 1; f <= model.face_count(); ++f) maps.push_back(make_surface_map(model, f));
    return maps;
}

}  // namespace tubemesh::geom
