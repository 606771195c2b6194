#pragma once
// Static bounding-box tree over the faces that never move: boundary triangles and obstacle
// quads. A grid would not do: a coarse surface mesh has triangles many times larger than the
// fronts, and a front close to a face must still find that face although none of its nodes
// is near (the case that keeps an apex inside the domain).
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/pyramids/geometry.hpp"

namespace tubemesh::pyramids {

class FaceTree {
public:
    explicit FaceTree(std::span<const Box> boxes);

    // Appends to `out` every face whose box overlaps `query`, in no particular order.
    // `stack` is caller scratch, so a query does not allocate once it has grown.
    void query(const Box& query, std::vector<index_t>& stack, std::vector<index_t>& out) const;

private:
    struct Node {
        Box box;
        index_t first;  // leaf: first slot in order_; inner: the left child
        index_t count;  // leaf: number of faces (> 0); inner: 0
        index_t right;  // inner: the right child
    };
    std::vector<Node> nodes_;
    std::vector<index_t> order_;
    std::vector<Box> boxes_;

    index_t build(index_t begin, index_t end);
};

}  // namespace tubemesh::pyramids
