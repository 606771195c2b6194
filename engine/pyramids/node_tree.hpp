#pragma once
// k-d tree (nanoflann) over the fixed nodes that can be candidate apexes or lie inside a new
// pyramid: the nodes of the boundary triangles and of the front quads. It keeps its own
// compact copy of their coordinates rather than indexing the whole point array, because
// most mesh points (the rings' interior and pipe-wall nodes) are never on the front, and
// because its queries write into caller scratch and so never allocate once warm — which
// tubemesh::PointIndex::within, allocating a result buffer per call, does not offer.
//
// Apexes created during the run are not in this tree: a front finds them through its
// neighbours' pyramids (fronts.hpp), so the tree never needs a rebuild.
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::pyramids {

class NodeTree {
public:
    // `nodes`: mesh point ids, sorted and unique.
    NodeTree(const HybridMesh& mesh, std::vector<index_t> nodes);
    ~NodeTree();
    NodeTree(const NodeTree&) = delete;
    NodeTree& operator=(const NodeTree&) = delete;

    // out = (mesh point id, squared distance) of the nodes strictly closer than `radius`,
    // in no particular order.
    void within(const Vec3& q, double radius, std::vector<std::pair<index_t, double>>& out) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tubemesh::pyramids
