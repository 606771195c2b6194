#include "engine/pyramids/face_tree.hpp"

#include <algorithm>

namespace tubemesh::pyramids {

namespace {
constexpr index_t kLeafSize = 4;

double axis(const Vec3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
}  // namespace

FaceTree::FaceTree(std::span<const Box> boxes) : boxes_(boxes.begin(), boxes.end()) {
    const auto n = static_cast<index_t>(boxes_.size());
    order_.resize(n);
    for (index_t i = 0; i < n; ++i) order_[i] = i;
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeafSize + 1));
    build(0, n);
}

// Median split on the longest axis of the centres' box.
index_t FaceTree::build(index_t begin, index_t end) {
    const auto me = static_cast<index_t>(nodes_.size());
    nodes_.push_back({});
    Box box = boxes_[order_[begin]];
    Box centres = Box::of(box.centre());
    for (index_t i = begin + 1; i < end; ++i) {
        box.add(boxes_[order_[i]]);
        centres.add(boxes_[order_[i]].centre());
    }
    nodes_[me].box = box;
    if (end - begin <= kLeafSize) {
        nodes_[me].first = begin;
        nodes_[me].count = end - begin;
        return me;
    }
    const Vec3 extent = centres.hi - centres.lo;
    const int a = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const index_t mid = begin + (end - begin) / 2;
    // Ties broken by face index: the tree, and so the query order, is reproducible.
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](index_t l, index_t r) {
        const double cl = axis(boxes_[l].centre(), a), cr = axis(boxes_[r].centre(), a);
        return cl < cr || (cl == cr && l < r);
    });
    const index_t left = build(begin, mid);
    const index_t right = build(mid, end);
    nodes_[me].first = left;
    nodes_[me].count = 0;
    nodes_[me].right = right;
    return me;
}

void FaceTree::query(const Box& q, std::vector<index_t>& stack, std::vector<index_t>& out) const {
    if (nodes_.empty()) return;
    stack.clear();
    stack.push_back(0);
    while (!stack.empty()) {
        const Node& node = nodes_[stack.back()];
        stack.pop_back();
        if (!node.box.overlaps(q)) continue;
        if (node.count > 0) {
            for (index_t k = node.first; k < node.first + node.count; ++k)
                if (boxes_[order_[k]].overlaps(q)) out.push_back(order_[k]);
        } else {
            stack.push_back(node.first);
            stack.push_back(node.right);
        }
    }
}

}  // namespace tubemesh::pyramids
