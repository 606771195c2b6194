#pragma once
// k-d tree over the fixed nodes that can be candidate apexes or lie inside a new pyramid:
// the nodes of the boundary triangles and of the front quads. It indexes its own compact copy
// of their coordinates rather than the whole point array, because most mesh points (the rings'
// interior and pipe-wall nodes) are never on the front.
//
// Apexes created during the run are not in this tree: a front finds them through its
// neighbours' pyramids (fronts.hpp), so the tree never needs a rebuild.
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/point_index.hpp"

namespace tubemesh::pyramids {

class NodeTree {
public:
    // `nodes`: mesh point ids, sorted and unique.
    NodeTree(const HybridMesh& mesh, std::vector<index_t> nodes);
    NodeTree(const NodeTree&) = delete;
    NodeTree& operator=(const NodeTree&) = delete;

    // out = (mesh point id, squared distance) of the nodes strictly closer than `radius`,
    // in no particular order; no allocation once `out` is warm.
    void within(const Vec3& q, double radius, std::vector<std::pair<index_t, double>>& out) const;

private:
    std::vector<index_t> ids_;
    std::vector<double> x_, y_, z_;  // must outlive the index, which reads them in place
    PointIndex index_;
};

}  // namespace tubemesh::pyramids
