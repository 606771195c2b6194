#include "engine/pyramids/node_tree.hpp"

#include <nanoflann.hpp>

namespace tubemesh::pyramids {

namespace {

struct Cloud {
    std::vector<double> x, y, z;
    std::size_t kdtree_get_point_count() const { return x.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return dim == 0 ? x[i] : dim == 1 ? y[i] : z[i]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud, double, index_t>, Cloud, 3,
                                                 index_t>;

}  // namespace

struct NodeTree::Impl {
    std::vector<index_t> ids;
    Cloud cloud;  // must outlive the tree, which keeps a reference to it
    Tree tree;
    Impl(const HybridMesh& mesh, std::vector<index_t> nodes)
        : ids(std::move(nodes)),
          cloud(gather(mesh, ids)),
          tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
        if (!ids.empty()) tree.buildIndex();
    }
    static Cloud gather(const HybridMesh& mesh, const std::vector<index_t>& ids) {
        Cloud c;
        c.x.reserve(ids.size());
        c.y.reserve(ids.size());
        c.z.reserve(ids.size());
        for (index_t i : ids) {
            c.x.push_back(mesh.x[i]);
            c.y.push_back(mesh.y[i]);
            c.z.push_back(mesh.z[i]);
        }
        return c;
    }
};

NodeTree::NodeTree(const HybridMesh& mesh, std::vector<index_t> nodes)
    : impl_(std::make_unique<Impl>(mesh, std::move(nodes))) {}

NodeTree::~NodeTree() = default;

void NodeTree::within(const Vec3& q, double radius, std::vector<std::pair<index_t, double>>& out) const {
    out.clear();
    if (impl_->ids.empty() || !(radius > 0)) return;
    const double p[3] = {q.x, q.y, q.z};
    // nanoflann 1.4: squared radius, strict comparison; it clears and refills `out`.
    impl_->tree.radiusSearch(p, radius * radius, out, nanoflann::SearchParams(32, 0.0f, false));
    for (auto& hit : out) hit.first = impl_->ids[hit.first];
}

}  // namespace tubemesh::pyramids
