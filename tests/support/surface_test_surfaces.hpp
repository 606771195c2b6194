#pragma once
// Analytic faces for the surface mesher's tests: plane, cylinder, cone, sphere, torus and a
// bicubic Bezier patch standing in for a B-spline, each a SurfaceMap over a uv rectangle, with
// exact area and distance-to-surface for the checks.
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh::testing {

class AnalyticSurface : public SurfaceMap {
public:
    AnalyticSurface(ParamRange u, ParamRange v, bool reversed = false, index_t id = 1)
        : u_(u), v_(v), reversed_(reversed), id_(id) {}

    index_t face() const override { return id_; }
    ParamRange u_range() const override { return u_; }
    ParamRange v_range() const override { return v_; }
    bool reversed() const override { return reversed_; }
    Vec3 point(Uv p) const override { return derivatives(p).point; }
    Projection project(const Vec3&, std::optional<Uv>) const override {
        throw Error("analytic test surface: project() is not used by the surface mesher");
    }
    Uv edge_uv(EdgeUse, double) const override { throw Error("analytic test surface: no B-rep edges"); }
    std::vector<TrimLoop> trimming_loops(double) const override { return {}; }

    // Distance of p from the (untrimmed) surface.
    virtual double distance(const Vec3& p) const = 0;
    // Area of the part of the surface over the uv rectangle [u0,u1] x [v0,v1].
    virtual double area(double u0, double u1, double v0, double v1) const = 0;
    // Largest normal curvature (0 for a plane): bounds the chord error of a mesh.
    virtual double max_curvature() const = 0;

private:
    ParamRange u_, v_;
    bool reversed_;
    index_t id_;
};

// origin + u·e1 + v·e2 (e1, e2 orthogonal, any length).
class PlaneSurface : public AnalyticSurface {
public:
    PlaneSurface(Vec3 origin, Vec3 e1, Vec3 e2, ParamRange u, ParamRange v, bool reversed = false, index_t id = 1)
        : AnalyticSurface(u, v, reversed, id), o_(origin), e1_(e1), e2_(e2) {}
    SurfaceDerivatives derivatives(Uv p) const override { return {o_ + p.u * e1_ + p.v * e2_, e1_, e2_}; }
    double distance(const Vec3& p) const override {
        const Vec3 n = cross(e1_, e2_);
        return std::abs(dot(p - o_, n)) / norm(n);
    }
    double area(double u0, double u1, double v0, double v1) const override {
        return (u1 - u0) * (v1 - v0) * norm(cross(e1_, e2_));
    }
    double max_curvature() const override { return 0; }

private:
    Vec3 o_, e1_, e2_;
};

// Axis z, radius r; u the angle, v the height.
class CylinderSurface : public AnalyticSurface {
public:
    CylinderSurface(double r, ParamRange u, ParamRange v) : AnalyticSurface(u, v), r_(r) {}
    SurfaceDerivatives derivatives(Uv p) const override {
        const double c = std::cos(p.u), s = std::sin(p.u);
        return {{r_ * c, r_ * s, p.v}, {-r_ * s, r_ * c, 0}, {0, 0, 1}};
    }
    double distance(const Vec3& p) const override { return std::abs(std::hypot(p.x, p.y) - r_); }
    double area(double u0, double u1, double v0, double v1) const override { return r_ * (u1 - u0) * (v1 - v0); }
    double max_curvature() const override { return 1 / r_; }

private:
    double r_;
};

// Axis z, half-angle alpha, radius r0 at v = 0; u the angle, v the length along a generator.
class ConeSurface : public AnalyticSurface {
public:
    ConeSurface(double r0, double alpha, ParamRange u, ParamRange v)
        : AnalyticSurface(u, v), r0_(r0), s_(std::sin(alpha)), c_(std::cos(alpha)) {}
    SurfaceDerivatives derivatives(Uv p) const override {
        const double r = r0_ + p.v * s_, cu = std::cos(p.u), su = std::sin(p.u);
        return {{r * cu, r * su, p.v * c_}, {-r * su, r * cu, 0}, {s_ * cu, s_ * su, c_}};
    }
    double distance(const Vec3& p) const override {
        // Signed distance to the line r = r0 + z tan(alpha) in the meridian plane.
        return std::abs((std::hypot(p.x, p.y) - r0_) * c_ - p.z * s_);
    }
    double area(double u0, double u1, double v0, double v1) const override {
        return (u1 - u0) * (r0_ * (v1 - v0) + 0.5 * s_ * (v1 * v1 - v0 * v0));
    }
    double max_curvature() const override { return c_ / r0_; }  // at the smaller end for v >= 0

private:
    double r0_, s_, c_;
};

// Centre 0, radius R; u the longitude, v the latitude.
class SphereSurface : public AnalyticSurface {
public:
    SphereSurface(double R, ParamRange u, ParamRange v) : AnalyticSurface(u, v), R_(R) {}
    SurfaceDerivatives derivatives(Uv p) const override {
        const double cu = std::cos(p.u), su = std::sin(p.u), cv = std::cos(p.v), sv = std::sin(p.v);
        return {{R_ * cv * cu, R_ * cv * su, R_ * sv}, {-R_ * cv * su, R_ * cv * cu, 0}, {-R_ * sv * cu, -R_ * sv * su, R_ * cv}};
    }
    double distance(const Vec3& p) const override { return std::abs(norm(p) - R_); }
    double area(double u0, double u1, double v0, double v1) const override {
        return R_ * R_ * (u1 - u0) * (std::sin(v1) - std::sin(v0));
    }
    double max_curvature() const override { return 1 / R_; }

private:
    double R_;
};

// Axis z, major radius R, minor radius r; u around the axis, v around the tube.
class TorusSurface : public AnalyticSurface {
public:
    TorusSurface(double R, double r, ParamRange u, ParamRange v) : AnalyticSurface(u, v), R_(R), r_(r) {}
    SurfaceDerivatives derivatives(Uv p) const override {
        const double cu = std::cos(p.u), su = std::sin(p.u), cv = std::cos(p.v), sv = std::sin(p.v);
        const double w = R_ + r_ * cv;
        return {{w * cu, w * su, r_ * sv}, {-w * su, w * cu, 0}, {-r_ * sv * cu, -r_ * sv * su, r_ * cv}};
    }
    double distance(const Vec3& p) const override { return std::abs(std::hypot(std::hypot(p.x, p.y) - R_, p.z) - r_); }
    double area(double u0, double u1, double v0, double v1) const override {
        return r_ * (u1 - u0) * (R_ * (v1 - v0) + r_ * (std::sin(v1) - std::sin(v0)));
    }
    double max_curvature() const override { return 1 / r_; }

private:
    double R_, r_;
};

// A bicubic Bezier patch over [0,1]^2 (a single-span B-spline): control points on a 4x4 grid
// of spacing `step` with heights z[i][j]. Area by Gauss quadrature, distance by Newton.
class BicubicSurface : public AnalyticSurface {
public:
    BicubicSurface(double step, const double (&z)[4][4]) : AnalyticSurface({0, 1}, {0, 1}) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) cp_[i][j] = {step * i, step * j, z[i][j]};
    }
    SurfaceDerivatives derivatives(Uv p) const override {
        double bu[4], du[4], bv[4], dv[4];
        basis(p.u, bu, du);
        basis(p.v, bv, dv);
        SurfaceDerivatives d{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                d.point = d.point + (bu[i] * bv[j]) * cp_[i][j];
                d.du = d.du + (du[i] * bv[j]) * cp_[i][j];
                d.dv = d.dv + (bu[i] * dv[j]) * cp_[i][j];
            }
        return d;
    }
    double distance(const Vec3& p) const override {
        // Gauss-Newton from the best of a coarse grid of starts.
        Uv best{0.5, 0.5};
        double bd = 1e300;
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 20; ++j) {
                const double d = norm(point({i / 20.0, j / 20.0}) - p);
                if (d < bd) bd = d, best = {i / 20.0, j / 20.0};
            }
        for (int it = 0; it < 30; ++it) {
            const SurfaceDerivatives d = derivatives(best);
            const Vec3 r = p - d.point;
            const double a = dot(d.du, d.du), b = dot(d.du, d.dv), c = dot(d.dv, d.dv);
            const double ru = dot(d.du, r), rv = dot(d.dv, r), det = a * c - b * b;
            best = {best.u + (c * ru - b * rv) / det, best.v + (a * rv - b * ru) / det};
        }
        return norm(point(best) - p);
    }
    double area(double u0, double u1, double v0, double v1) const override {
        // 8-point Gauss-Legendre on a 16 x 16 grid of cells: far below any mesh error.
        static constexpr double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                        -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                        0.7966664774136267,  0.9602898564975363};
        static constexpr double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                        0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                        0.2223810344533745, 0.1012285362903763};
        const int cells = 16;
        const double hu = (u1 - u0) / cells, hv = (v1 - v0) / cells;
        double sum = 0;
        for (int ci = 0; ci < cells; ++ci)
            for (int cj = 0; cj < cells; ++cj)
                for (int a = 0; a < 8; ++a)
                    for (int b = 0; b < 8; ++b) {
                        const Uv p{u0 + hu * (ci + 0.5 + 0.5 * x[a]), v0 + hv * (cj + 0.5 + 0.5 * x[b])};
                        const SurfaceDerivatives d = derivatives(p);
                        sum += w[a] * w[b] * norm(cross(d.du, d.dv));
                    }
        return sum * hu * hv / 4;
    }
    double max_curvature() const override { return max_curvature_; }
    void set_max_curvature(double k) { max_curvature_ = k; }

private:
    static void basis(double t, double* b, double* d) {
        const double s = 1 - t;
        b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
        d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
    }
    Vec3 cp_[4][4];
    double max_curvature_ = 0;
};

}  // namespace tubemesh::testing
