#include "engine/sizing/control_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

ControlSpace::ControlSpace(const TetDomain& domain, const ControlSpaceOptions& options) {
    if (domain.front.empty() || domain.front_points == 0)
        throw Error("control space: the tet domain has no front triangles to take sizes from");
    if (!(options.gradation >= 1.0)) throw Error("control space: the gradation factor must be at least 1");
    if (!(options.far_size >= 0.0)) throw Error("control space: the far size must not be negative");
    const index_t n = domain.front_points;
    x_.resize(n);
    y_.resize(n);
    z_.resize(n);
    for (index_t i = 0; i < n; ++i) {
        x_[i] = domain.point(i)[0];
        y_[i] = domain.point(i)[1];
        z_[i] = domain.point(i)[2];
    }
    // Every front edge is met twice (once per adjacent triangle): the means are unaffected.
    std::vector<double> sum(n, 0.0);
    std::vector<index_t> count(n, 0);
    for (std::size_t t = 0; t + 2 < domain.front.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const index_t a = domain.front[t + k], b = domain.front[t + (k + 1) % 3];
            const double* pa = domain.point(a);
            const double* pb = domain.point(b);
            const double len = std::hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]);
            sum[a] += len;
            sum[b] += len;
            count[a] += 1;
            count[b] += 1;
        }
    node_size_.assign(n, 0.0);
    double largest = 0;
    for (index_t i = 0; i < n; ++i)
        if (count[i]) {
            node_size_[i] = sum[i] / count[i];
            largest = std::max(largest, node_size_[i]);
        }
    // Nodes on no front triangle (not expected) take the largest size: they never shrink h.
    for (index_t i = 0; i < n; ++i)
        if (!count[i]) node_size_[i] = largest;
    far_size_ = options.far_size > 0 ? options.far_size : largest;
    // size() is a min of far_size_ and node_size_[i] + (non-negative): never below this.
    smallest_size_ = std::min(far_size_, *std::min_element(node_size_.begin(), node_size_.end()));
    slope_ = options.gradation - 1.0;
    // A node whose squared distance (as the index computes it) is at least far_reach_^2 has
    // slope * d above S - smallest even after the rounding of R, R^2, the square root and the
    // product (a few ulps; the margin is 1e-6), so the real sum s_i + slope d exceeds S, and its
    // rounding, which keeps order, is at least S (a double): size() is then S exactly. With S
    // at or below every node's size h is S everywhere (reach 0). No shortcut without grading,
    // nor where R^2 would underflow (it could no longer tell a node at distance 0).
    const double inf = std::numeric_limits<double>::infinity();
    if (far_size_ <= smallest_size_) {
        far_reach_ = 0;
    } else if (slope_ > 0) {
        const double r = (far_size_ - smallest_size_) / slope_ * (1 + 1e-6);
        far_reach_ = r * r >= std::numeric_limits<double>::min() ? r : inf;
    } else {
        far_reach_ = inf;
    }
    neighbours_ = std::max<index_t>(options.neighbours, 1);
    index_ = std::make_unique<PointIndex>(x_, y_, z_);
}

ControlSpace::~ControlSpace() = default;

double ControlSpace::size(const double* p) const { return std::min(far_size_, sample(p).uncapped); }

double ControlSpace::size_if_far(const double* p) const {
    if (far_reach_ == 0) return far_size_;
    if (std::isfinite(far_reach_) && !index_->any_within({p[0], p[1], p[2]}, far_reach_)) return far_size_;
    return size(p);
}

bool ControlSpace::far_and_clear(const double* p, double clearance) const {
    // The clearance with the same margin: a node at or beyond it is beyond `clearance` too
    // (a reach whose square would underflow, or a NaN clearance, takes the full query).
    const double reach = std::max(far_reach_, clearance * (1 + 1e-6));
    if (std::isfinite(reach) && reach * reach >= std::numeric_limits<double>::min() && !std::isnan(clearance) &&
        !index_->any_within({p[0], p[1], p[2]}, reach))
        return true;
    const Sample s = sample(p);
    return s.uncapped >= far_size_ && s.nearest_front >= clearance;
}

ControlSpace::Sample ControlSpace::sample(const double* p) const {
    // The minima do not depend on the order of the neighbours: skip nearest()'s sort.
    NearestBuffer buffer(neighbours_);
    index_t* idx = buffer.index();
    double* d2 = buffer.distance_squared();
    const index_t found = index_->nearest_unordered({p[0], p[1], p[2]}, neighbours_, idx, d2);
    Sample s{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    for (index_t i = 0; i < found; ++i) {
        const double d = std::sqrt(d2[i]);
        s.uncapped = std::min(s.uncapped, node_size_[idx[i]] + slope_ * d);
        s.nearest_front = std::min(s.nearest_front, d);
    }
    return s;
}

}  // namespace tubemesh::tets

namespace tubemesh::tets {

index_t ControlSpace::source(const double* p) const {
    NearestBuffer buffer(neighbours_);
    index_t* idx = buffer.index();
    double* d2 = buffer.distance_squared();
    const index_t found = index_->nearest_unordered({p[0], p[1], p[2]}, neighbours_, idx, d2);
    index_t best = idx[0];
    double h = std::numeric_limits<double>::infinity();
    // Ties to the lowest node id: the same answer whatever order the query returns.
    for (index_t i = 0; i < found; ++i) {
        const double t = node_size_[idx[i]] + slope_ * std::sqrt(d2[i]);
        if (t < h || (t == h && idx[i] < best)) {
            h = t;
            best = idx[i];
        }
    }
    return best;
}

}  // namespace tubemesh::tets
