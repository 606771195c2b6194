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

    // All points strictly closer than `radius`, nearest first, ties by index.
    void within(const Vec3& query, double radius, std::vector<Neighbor>& out) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tubemesh
