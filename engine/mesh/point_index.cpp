#include "engine/mesh/point_index.hpp"

#include <algorithm>
#include <nanoflann.hpp>

namespace tubemesh {

namespace {

// nanoflann 1.4 adaptor over three coordinate arrays.
struct SoaCloud {
    std::span<const double> x, y, z;
    std::size_t kdtree_get_point_count() const { return x.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return dim == 0 ? x[i] : dim == 1 ? y[i] : z[i]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, SoaCloud, double, index_t>,
                                                 SoaCloud, 3, index_t>;

// A nanoflann result set that ends the search at the first point strictly inside the radius.
struct FirstWithin {
    double radius_squared;
    bool found = false;
    bool full() const { return true; }
    double worstDist() const { return radius_squared; }
    bool addPoint(double distance_squared, index_t) {
        if (!(distance_squared < radius_squared)) return true;
        found = true;
        return false;  // stop searching
    }
};

bool closer(const Neighbor& a, const Neighbor& b) {
    return a.distance_squared < b.distance_squared ||
           (a.distance_squared == b.distance_squared && a.index < b.index);
}

}  // namespace

struct PointIndex::Impl {
    SoaCloud cloud;  // must outlive the tree, which keeps a reference to it
    Tree tree;
    Impl(std::span<const double> x, std::span<const double> y, std::span<const double> z)
        : cloud{x, y, z}, tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}  // builds the tree
};

PointIndex::PointIndex(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    if (y.size() != x.size() || z.size() != x.size()) throw Error("PointIndex: coordinate arrays differ in length");
    impl_ = std::make_unique<Impl>(x, y, z);
}

PointIndex::~PointIndex() = default;

index_t PointIndex::size() const { return static_cast<index_t>(impl_->cloud.x.size()); }

void PointIndex::nearest(const Vec3& query, index_t k, std::vector<Neighbor>& out) const {
    out.clear();
    if (k == 0 || size() == 0) return;
    const std::size_t want = std::min<std::size_t>(k, size());
    NearestBuffer buffer(static_cast<index_t>(want));
    index_t* idx = buffer.index();
    double* d2 = buffer.distance_squared();
    const index_t found = nearest_unordered(query, k, idx, d2);
    out.resize(found);
    for (index_t i = 0; i < found; ++i) out[i] = {idx[i], d2[i]};
    // nanoflann's own order among equal distances depends on the tree layout: re-sort by
    // (distance, index) so callers see one documented order.
    std::sort(out.begin(), out.end(), closer);
}

index_t PointIndex::nearest_unordered(const Vec3& query, index_t k, index_t* idx, double* distance_squared) const {
    if (k == 0 || size() == 0) return 0;
    const double q[3] = {query.x, query.y, query.z};
    const std::size_t want = std::min<std::size_t>(k, size());
    return static_cast<index_t>(impl_->tree.knnSearch(q, want, idx, distance_squared));
}

void PointIndex::within(const Vec3& query, double radius, std::vector<Neighbor>& out) const {
    out.clear();
    std::vector<std::pair<index_t, double>> hits;
    within_unordered(query, radius, hits);
    out.reserve(hits.size());
    for (const auto& [i, d2] : hits) out.push_back({i, d2});
    std::sort(out.begin(), out.end(), closer);
}

void PointIndex::within_unordered(const Vec3& query, double radius,
                                  std::vector<std::pair<index_t, double>>& out) const {
    out.clear();
    if (!(radius > 0.0) || size() == 0) return;
    const double q[3] = {query.x, query.y, query.z};
    // nanoflann 1.4: squared radius, strict comparison; it clears and refills `out`.
    impl_->tree.radiusSearch(q, radius * radius, out, nanoflann::SearchParams(32, 0.0f, false));
}

bool PointIndex::any_within(const Vec3& query, double radius) const {
    if (!(radius > 0.0) || size() == 0) return false;
    const double q[3] = {query.x, query.y, query.z};
    FirstWithin first{radius * radius};
    impl_->tree.findNeighbors(first, q, nanoflann::SearchParams(32, 0.0f, false));
    return first.found;
}

}  // namespace tubemesh
