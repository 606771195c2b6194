#include "geom/tubes/tubes_loop.hpp"

#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>

#include <algorithm>
#include <cmath>

#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

// Relative accuracy of arc lengths: far below anything the mesh can see, still cheap for the
// Gauss integration GCPnts uses.
constexpr double kLengthTolerance = 1e-10;

}  // namespace

LoopCurve::LoopCurve(const Model& model, const HoleLoop& loop) {
    for (const LoopEdge& le : loop.edges) {
        const TopoDS_Edge edge = edge_of(model, le.edge);
        if (BRep_Tool::Degenerated(edge)) continue;
        Handle(BRepAdaptor_Curve) curve = new BRepAdaptor_Curve(edge);
        const double t0 = curve->FirstParameter(), t1 = curve->LastParameter();
        const double len = GCPnts_AbscissaPoint::Length(*curve, t0, t1, kLengthTolerance);
        items_.push_back({le.edge, le.forward, curve, t0, t1, length_, len});
        length_ += len;
    }
}

double LoopCurve::param_at(const Item& item, double ds) const {
    ds = std::clamp(ds, 0.0, item.length);
    const double tol = kLengthTolerance * std::max(item.length, 1e-300);
    if (item.forward) return GCPnts_AbscissaPoint(tol, *item.curve, ds, item.t0).Parameter();
    return GCPnts_AbscissaPoint(tol, *item.curve, -ds, item.t1).Parameter();
}

LoopPoint LoopCurve::at(double s) const {
    s = std::fmod(s, length_);
    if (s < 0) s += length_;
    // The last item whose start is at or before s.
    auto it = std::upper_bound(items_.begin(), items_.end(), s, [](double v, const Item& i) { return v < i.s0; });
    const int k = static_cast<int>(std::max<std::ptrdiff_t>(0, (it - items_.begin()) - 1));
    const Item& item = items_[k];
    const double t = param_at(item, s - item.s0);
    return {k, t, s, item.curve->Value(t)};
}

std::optional<LoopPoint> LoopCurve::locate(int edge, double t) const {
    for (int k = 0; k < edge_count(); ++k) {
        const Item& item = items_[k];
        if (item.id != edge) continue;
        t = std::clamp(t, item.t0, item.t1);
        const double ds = item.forward ? GCPnts_AbscissaPoint::Length(*item.curve, item.t0, t, kLengthTolerance)
                                       : GCPnts_AbscissaPoint::Length(*item.curve, t, item.t1, kLengthTolerance);
        double s = item.s0 + ds;
        if (s >= length_) s -= length_;
        return LoopPoint{k, t, s, item.curve->Value(t)};
    }
    return std::nullopt;
}

}  // namespace tubemesh::geom
