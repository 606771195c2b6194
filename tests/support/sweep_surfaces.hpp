#pragma once
// Analytic faces for the sweep's tests, with the exact foot-point projection the sweep needs:
// planes and cylinders for host faces, cylinders and tori for tube walls. Periodic parameters
// are folded into a window centred on the face's range, so a point just past a face's end
// comes out just outside the range, as geom's projection onto the untrimmed surface does.
// Walls can also project "clamped", as onto a bounded B-spline surface: into the face's ranges.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/geometry/surface_map.hpp"

namespace tubemesh::sweep_testing {

using V = Eigen::Vector3d;
inline Vec3 vec(const V& p) { return {p.x(), p.y(), p.z()}; }
inline V eig(const Vec3& p) { return {p.x, p.y, p.z}; }
inline constexpr double kPi = std::numbers::pi;

class TestSurface : public SurfaceMap {
public:
    TestSurface(index_t id, ParamRange u, ParamRange v, bool reversed) : id_(id), u_(u), v_(v), reversed_(reversed) {}

    index_t face() const override { return id_; }
    ParamRange u_range() const override { return u_; }
    ParamRange v_range() const override { return v_; }
    bool reversed() const override { return reversed_; }
    Vec3 point(Uv uv) const override { return derivatives(uv).point; }
    Uv edge_uv(EdgeUse, double) const override { throw Error("sweep test surface: no B-rep edges"); }
    std::vector<TrimLoop> trimming_loops(double) const override { return {}; }

    // Distance from the face itself: +infinity when the foot point is off its ranges.
    double distance_on_face(const Vec3& p) const {
        const Projection pr = project(p, std::nullopt);
        if (!pr.ok || !within(u_, pr.uv.u) || !within(v_, pr.uv.v)) return std::numeric_limits<double>::infinity();
        return pr.distance;
    }

protected:
    static double fold(const ParamRange& r, double t) {
        if (!(r.period > 0)) return t;
        const double mid = 0.5 * (r.lo + r.hi);
        return t - r.period * std::floor((t - (mid - 0.5 * r.period)) / r.period);
    }
    static bool within(const ParamRange& r, double t) {
        const double tol = 1e-9 * (r.hi - r.lo);
        return r.closed || (t >= r.lo - tol && t <= r.hi + tol);
    }
    Projection found(Uv uv, double distance) const {
        uv = {fold(u_, uv.u), fold(v_, uv.v)};
        return {true, uv, point(uv), distance};
    }
    // As a bounded surface (a B-spline) projects: the foot of the unbounded surface moved
    // into the face's ranges, its distance measured honestly.
    Projection clamp_to_face(const Vec3& p, Uv uv) const {
        uv = {fold(u_, uv.u), fold(v_, uv.v)};
        if (!u_.closed) uv.u = std::clamp(uv.u, u_.lo, u_.hi);
        if (!v_.closed) uv.v = std::clamp(uv.v, v_.lo, v_.hi);
        const Vec3 foot = point(uv);
        return {true, uv, foot, (eig(p) - eig(foot)).norm()};
    }

private:
    index_t id_;
    ParamRange u_, v_;
    bool reversed_;
};

// Through `origin` with outward normal `normal`: u, v along two orthonormal in-plane axes.
class PlaneFace : public TestSurface {
public:
    PlaneFace(index_t id, const V& origin, const V& normal, double half_size)
        : TestSurface(id, {-half_size, half_size}, {-half_size, half_size}, false),
          o_(origin), n_(normal.normalized()) {
        e1_ = n_.unitOrthogonal();
        e2_ = n_.cross(e1_);  // e1 x e2 = n: the natural normal is the outward one
    }
    SurfaceDerivatives derivatives(Uv p) const override { return {vec(o_ + p.u * e1_ + p.v * e2_), vec(e1_), vec(e2_)}; }
    Projection project(const Vec3& p, std::optional<Uv>) const override {
        const V q = eig(p) - o_;
        return found({q.dot(e1_), q.dot(e2_)}, std::abs(q.dot(n_)));
    }

private:
    V o_, n_, e1_, e2_;
};

// Axis through `a` along unit `d`; u the angle from `e1` (right-handed about d), v the
// distance along d. `outward_from_axis`: the solid is inside (a journal); otherwise outside
// (a tube's hole: the solid's outward normal points at the axis).
class CylinderFace : public TestSurface {
public:
    CylinderFace(index_t id, const V& a, const V& d, const V& e1, double radius, ParamRange u, ParamRange v,
                 bool outward_from_axis, bool clamped = false)
        : TestSurface(id, u, v, !outward_from_axis), a_(a), d_(d.normalized()), r_(radius), clamped_(clamped) {
        e1_ = (e1 - d_.dot(e1) * d_).normalized();
        e2_ = d_.cross(e1_);
    }
    SurfaceDerivatives derivatives(Uv p) const override {
        const double c = std::cos(p.u), s = std::sin(p.u);
        return {vec(a_ + r_ * (c * e1_ + s * e2_) + p.v * d_), vec(r_ * (-s * e1_ + c * e2_)), vec(d_)};
    }
    Projection project(const Vec3& p, std::optional<Uv>) const override {
        const V q = eig(p) - a_;
        const double along = q.dot(d_);
        const V radial = q - along * d_;
        if (!(radial.norm() > 1e-14 * r_)) return {};
        const Uv uv{std::atan2(radial.dot(e2_), radial.dot(e1_)), along};
        if (clamped_) return clamp_to_face(p, uv);
        return found(uv, std::abs(radial.norm() - r_));
    }

private:
    V a_, d_, e1_, e2_;
    double r_;
    bool clamped_;
};

// Centre circle of radius R about axis z through c, starting along x (y = z x x); minor
// radius r. u: angle about z from x (the face spans u in its range), v: angle around the
// tube (closed). The solid is outside the tube: the outward normal points at the centre circle.
class TorusFace : public TestSurface {
public:
    TorusFace(index_t id, const V& c, const V& z, const V& x, double R, double r, double u0, double u1,
              bool clamped = false)
        : TestSurface(id, {u0, u1, false, 2 * kPi}, {0, 2 * kPi, true, 2 * kPi}, true), c_(c), z_(z.normalized()),
          R_(R), r_(r), clamped_(clamped) {
        x_ = (x - z_.dot(x) * z_).normalized();
        y_ = z_.cross(x_);
    }
    SurfaceDerivatives derivatives(Uv p) const override {
        const V radial = std::cos(p.u) * x_ + std::sin(p.u) * y_, across = -std::sin(p.u) * x_ + std::cos(p.u) * y_;
        const double cv = std::cos(p.v), sv = std::sin(p.v);
        return {vec(c_ + (R_ + r_ * cv) * radial + r_ * sv * z_), vec((R_ + r_ * cv) * across),
                vec(r_ * (-sv * radial + cv * z_))};
    }
    Projection project(const Vec3& p, std::optional<Uv>) const override {
        const V q = eig(p) - c_;
        const double h = q.dot(z_);
        const double rho = (q - h * z_).norm();
        if (!(rho > 1e-14 * R_)) return {};
        const double w = rho - R_;
        if (!(std::hypot(w, h) > 1e-14 * r_)) return {};
        const Uv uv{std::atan2(q.dot(y_), q.dot(x_)), std::atan2(h, w)};
        if (clamped_) return clamp_to_face(p, uv);
        return found(uv, std::abs(std::hypot(w, h) - r_));
    }

private:
    V c_, z_, x_, y_;
    double R_, r_;
    bool clamped_;
};

}  // namespace tubemesh::sweep_testing
