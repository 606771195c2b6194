#pragma once
// The tet step's target size h(x) (paper §5): the front's local sizes (mean length of the front
// edges at each front node), graded away from the front towards the far size S. With gradation
// g, h may grow by at most the factor g per element: h(x) = min(S, min_i s_i + (g - 1) |x - x_i|),
// the minimum taken over the k front nodes nearest x (a nanoflann query, engine/mesh/point_index).
#include <cmath>
#include <memory>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/point_index.hpp"

namespace tubemesh::tets {

struct TetDomain;

struct ControlSpaceOptions {
    // Far size S; 0 = the largest local size of the front.
    double far_size = 0;
    // Largest growth of h from one element to the next; 1.4 (1 = uniform front size).
    double gradation = 1.4;
    // Front nodes consulted per query (the nearest ones); 8.
    index_t neighbours = 8;
};

class ControlSpace {
public:
    // Throws tubemesh::Error when the domain has no front or the options are out of range.
    explicit ControlSpace(const TetDomain& domain, const ControlSpaceOptions& options = {});
    ~ControlSpace();
    ControlSpace(const ControlSpace&) = delete;
    ControlSpace& operator=(const ControlSpace&) = delete;

    // Target edge length at p; thread-safe.
    double size(const double* p) const;
    // size(p) before the cap at the far size, and the distance from p to the nearest front node.
    struct Sample {
        double uncapped = 0;
        double nearest_front = 0;
    };
    Sample sample(const double* p) const;
    // The front node whose term decides size(p) before the cap: the argmin of
    // node_size(i) + slope() |p - node(i)| over the nodes size() consults. One k-nearest query,
    // as size(p); with it, term(i, q) gives h at points q near p without a query (carried_size).
    index_t source(const double* p) const;
    // node_size(i) + slope() |p - node(i)|.
    double term(index_t i, const double* p) const {
        const double dx = p[0] - x_[i], dy = p[1] - y_[i], dz = p[2] - z_[i];
        return node_size_[i] + slope_ * std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    // size(p), the same value, for a point likely to lie where h has reached S (a caller's hint,
    // such as a face whose points are all at S): when no front node lies within far_reach() of
    // p, every node's term is at least S and one "any node within" query answers; otherwise
    // the k-nearest query does. Far from the front the k nearest lie far away and that query
    // visits many cells (a lift at S 0.11: a tenth of the run went to it).
    double size_if_far(const double* p) const;
    // sample(p).uncapped >= far_size() && sample(p).nearest_front >= clearance, answered the
    // same way: with no front node within max(far_reach(), clearance) of p, both hold.
    bool far_and_clear(const double* p, double clearance) const;
    // Beyond this distance from every front node h is S: (S - smallest node size) / (g - 1),
    // with a relative margin of 1e-6 so that rounding never decides it; 0 when S is at or
    // below every node's size, infinite (no shortcut) for g = 1 or a reach too small to square.
    double far_reach() const { return far_reach_; }
    // Local size of front node i (mean incident front edge length).
    double node_size(index_t i) const { return node_size_[i]; }
    double far_size() const { return far_size_; }
    // The most h grows per unit length: gradation - 1.
    double slope() const { return slope_; }
    // No size() result is below this: min(far size, smallest node size).
    double smallest_size() const { return smallest_size_; }

private:
    std::vector<double> x_, y_, z_;  // front nodes, read in place by the index
    std::vector<double> node_size_;
    double far_size_ = 0;
    double smallest_size_ = 0;
    double slope_ = 0;
    double far_reach_ = 0;
    index_t neighbours_ = 8;
    std::unique_ptr<PointIndex> index_;
};

}  // namespace tubemesh::tets
