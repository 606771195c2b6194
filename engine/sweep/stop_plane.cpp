#include "engine/sweep/stop_plane.hpp"

#include <cmath>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh::sweep {
namespace {

class StopPlane final : public SurfaceMap {
public:
    StopPlane(const Vec3& origin, const Vec3& normal, double half_size) : o_(origin), n_(normalized(normal)), half_(half_size) {
        const Vec3 a = std::abs(n_.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        e1_ = normalized(cross(n_, a));
        e2_ = cross(n_, e1_);  // e1 x e2 = n: the natural normal is the outward one
    }
    index_t face() const override { return 0; }
    ParamRange u_range() const override { return {-half_, half_}; }
    ParamRange v_range() const override { return {-half_, half_}; }
    bool reversed() const override { return false; }
    Vec3 point(Uv uv) const override { return o_ + uv.u * e1_ + uv.v * e2_; }
    SurfaceDerivatives derivatives(Uv uv) const override { return {point(uv), e1_, e2_}; }
    Projection project(const Vec3& p, std::optional<Uv>) const override {
        const Vec3 q = p - o_;
        const Uv uv{dot(q, e1_), dot(q, e2_)};
        return {true, uv, point(uv), std::abs(dot(q, n_))};
    }
    Uv edge_uv(EdgeUse, double) const override { throw Error("a ring's stop plane has no B-rep edges"); }
    std::vector<TrimLoop> trimming_loops(double) const override { return {}; }

private:
    Vec3 o_, n_, e1_, e2_;
    double half_;
};

}  // namespace

std::shared_ptr<const SurfaceMap> stop_plane(const Vec3& centre, const Vec3& tangent, bool last_end, double radius) {
    return std::make_shared<StopPlane>(centre, last_end ? tangent : -tangent, 1e3 * radius);
}

}  // namespace tubemesh::sweep
