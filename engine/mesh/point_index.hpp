#pragma once
// k-d tree over the mesh's point arrays, read in place (no copy of the coordinates).
// The index refers to the arrays it was built on: rebuild it after points are added or moved.
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

struct Neighbor {
    index_t index;
    double distance_squared;
    bool operator==(const Neighbor&) const = default;
};

// Room for the results of a k-nearest query: on the stack for k <= 32 (the common case: no
// heap allocation per query), on the heap beyond.
class NearestBuffer {
public:
    explicit NearestBuffer(index_t k) {
        if (k > kOnStack) {
            idx_heap_.resize(k);
            d2_heap_.resize(k);
            idx_ = idx_heap_.data();
            d2_ = d2_heap_.data();
        }
    }
    NearestBuffer(const NearestBuffer&) = delete;
    NearestBuffer& operator=(const NearestBuffer&) = delete;
    index_t* index() { return idx_; }
    double* distance_squared() { return d2_; }

private:
    static constexpr index_t kOnStack = 32;
    index_t idx_stack_[kOnStack];
    double d2_stack_[kOnStack];
    std::vector<index_t> idx_heap_;
    std::vector<double> d2_heap_;
    index_t* idx_ = idx_stack_;
    double* d2_ = d2_stack_;
};

class PointIndex {
public:
    PointIndex(std::span<const double> x, std::span<const double> y, std::span<const double> z);
    explicit PointIndex(const HybridMesh& mesh) : PointIndex(mesh.x, mesh.y, mesh.z) {}
    ~PointIndex();
    PointIndex(const PointIndex&) = delete;
    PointIndex& operator=(const PointIndex&) = delete;

    index_t size() const;

    // The k nearest points, nearest first, equal distances by increasing index. Fewer than k
    // when the index holds fewer points.
    void nearest(const Vec3& query, index_t k, std::vector<Neighbor>& out) const;

    // The same k points as nearest() (fewer when the index holds fewer), written to idx and
    // distance_squared (room for k each) in no documented order; returns how many. For callers
    // that reduce over the set, such as a minimum: no sorting and no allocation.
    index_t nearest_unordered(const Vec3& query, index_t k, index_t* idx, double* distance_squared) const;

    // All points strictly closer than `radius`, nearest first, ties by index.
    void within(const Vec3& query, double radius, std::vector<Neighbor>& out) const;

    // The same points as within() as (index, squared distance) in the tree's own order, which
    // depends only on the points: for callers that sort or reduce the set themselves. `out` is
    // cleared and refilled, so a caller that keeps it allocates nothing once it is warm.
    void within_unordered(const Vec3& query, double radius, std::vector<std::pair<index_t, double>>& out) const;

    // Whether some point is strictly closer than `radius` (within() would list one): the search
    // stops at the first such point, with no list and no allocation.
    bool any_within(const Vec3& query, double radius) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tubemesh
