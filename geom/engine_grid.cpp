#include "geom/engine_grid.hpp"

#include <algorithm>
#include <cmath>

namespace tubemesh::geom {

namespace {

// x on steps of `step` (a power of two: the product is exact); + 0.0 makes -0 a 0, which
// std::atan2 and the sign tests would tell apart.
double on_steps(double x, double step) { return std::nearbyint(x / step) * step + 0.0; }

// The largest power of two not above x > 0, times 2^-bits. x is first raised by 2^-20 of itself,
// so a length that is a power of two (a face 4 long) and the same length one rounding below it
// get the same step.
double step_below(double x, int bits) {
    int e = 0;
    std::frexp(x * (1 + 0x1p-20), &e);  // = f · 2^e, f in [0.5, 1)
    return std::ldexp(1.0, e - 1 - bits);
}

}  // namespace

EngineGrid::EngineGrid(double diagonal, int bits)
    : bits_(bits), step_(diagonal > 0 && std::isfinite(diagonal) ? step_below(diagonal, bits) : 0) {}

double EngineGrid::length(double x) const { return step_ > 0 ? on_steps(x, step_) : x; }

Vec3 EngineGrid::point(const Vec3& p) const { return {length(p.x), length(p.y), length(p.z)}; }

Vec3 EngineGrid::vector(const Vec3& v) const {
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0) || !std::isfinite(largest)) return v;
    const double step = step_below(largest, bits_);
    return {on_steps(v.x, step), on_steps(v.y, step), on_steps(v.z, step)};
}

double EngineGrid::parameter(double t, double extent) const {
    if (!(extent > 0) || !std::isfinite(extent)) return t;
    return on_steps(t, step_below(extent, bits_));
}

void snap(DiscreteGeometry& g, const EngineGrid& grid) {
    g.size = grid.length(g.size);
    g.sweep_size = grid.length(g.sweep_size);
    for (TubeData& t : g.tubes) {
        for (TubeStation& s : t.stations) {
            s.centre = grid.point(s.centre);
            s.tangent = grid.vector(s.tangent);
            s.reference = grid.vector(s.reference);
            s.radius = grid.length(s.radius);
        }
        for (Vec3& p : t.ring1) p = grid.point(p);
        for (Vec3& p : t.ring2) p = grid.point(p);
        for (double& s : t.room.s) s = grid.length(s);
        for (Vec3& v : t.room.tangent) v = grid.vector(v);
        for (Vec3& v : t.room.u) v = grid.vector(v);
        for (double& x : t.room.thickness) x = grid.length(x);
    }
    for (EdgePolyline& e : g.edges) {
        for (Vec3& p : e.points) p = grid.point(p);
        if (e.params.size() < 2) continue;
        const double extent = e.params.back() - e.params.front();
        for (double& t : e.params) t = grid.parameter(t, extent);
    }
}

void snap(std::vector<SizeSource>& sources, const EngineGrid& grid) {
    for (SizeSource& s : sources) s = {grid.point(s.point), grid.length(s.size)};
}

namespace {

class GridSurfaceMap final : public SurfaceMap {
public:
    GridSurfaceMap(std::unique_ptr<SurfaceMap> map, const EngineGrid& grid)
        : map_(std::move(map)), grid_(grid), u_(snapped(map_->u_range())), v_(snapped(map_->v_range())) {}

    index_t face() const override { return map_->face(); }
    ParamRange u_range() const override { return u_; }
    ParamRange v_range() const override { return v_; }
    bool reversed() const override { return map_->reversed(); }

    Vec3 point(Uv uv) const override { return grid_.point(map_->point(uv)); }
    SurfaceDerivatives derivatives(Uv uv) const override {
        const SurfaceDerivatives d = map_->derivatives(uv);
        return {grid_.point(d.point), grid_.vector(d.du), grid_.vector(d.dv)};
    }
    Projection project(const Vec3& p, std::optional<Uv> hint) const override {
        Projection r = map_->project(p, hint);
        r.uv = uv(r.uv);
        r.point = grid_.point(r.point);
        r.distance = grid_.length(r.distance);
        return r;
    }
    Uv edge_uv(EdgeUse use, double t) const override { return uv(map_->edge_uv(use, t)); }
    std::vector<TrimLoop> trimming_loops(double max_step) const override {
        std::vector<TrimLoop> loops = map_->trimming_loops(max_step);
        for (TrimLoop& l : loops)
            for (Uv& p : l.uv) p = uv(p);
        return loops;
    }

private:
    static double extent(const ParamRange& r) { return r.period > 0 ? r.period : r.hi - r.lo; }
    ParamRange snapped(ParamRange r) const {
        const double e = extent(r);
        r.lo = grid_.parameter(r.lo, e);
        r.hi = grid_.parameter(r.hi, e);
        return r;  // the period is the surface's own (2π, a B-spline's knot span): left exact
    }
    Uv uv(Uv p) const { return {grid_.parameter(p.u, extent(u_)), grid_.parameter(p.v, extent(v_))}; }

    std::unique_ptr<SurfaceMap> map_;
    EngineGrid grid_;
    ParamRange u_, v_;
};

}  // namespace

std::unique_ptr<SurfaceMap> on_grid(std::unique_ptr<SurfaceMap> map, const EngineGrid& grid) {
    return std::make_unique<GridSurfaceMap>(std::move(map), grid);
}

}  // namespace tubemesh::geom
