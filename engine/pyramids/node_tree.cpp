#include "engine/pyramids/node_tree.hpp"

namespace tubemesh::pyramids {

namespace {

std::vector<double> gather(std::span<const double> coordinate, const std::vector<index_t>& ids) {
    std::vector<double> out;
    out.reserve(ids.size());
    for (index_t i : ids) out.push_back(coordinate[i]);
    return out;
}

}  // namespace

NodeTree::NodeTree(const HybridMesh& mesh, std::vector<index_t> nodes)
    : ids_(std::move(nodes)),
      x_(gather(mesh.x, ids_)),
      y_(gather(mesh.y, ids_)),
      z_(gather(mesh.z, ids_)),
      index_(x_, y_, z_) {}

void NodeTree::within(const Vec3& q, double radius, std::vector<std::pair<index_t, double>>& out) const {
    index_.within_unordered(q, radius, out);
    for (auto& hit : out) hit.first = ids_[hit.first];
}

}  // namespace tubemesh::pyramids
