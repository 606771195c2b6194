#pragma once
// Conflict-free batches: a greedy colouring of the neighbour graph restricted to the fronts
// of one pass. Fronts of one colour are pairwise not neighbours, so none can see what
// another builds: they are evaluated concurrently against the same state and committed one
// after the other, and the result is the same as a serial run in that order.
//
// The colouring walks the fronts in the pass's order and gives each the smallest colour its
// already coloured neighbours do not use, so it depends only on that order and the graph:
// the batches, and with them the mesh, do not depend on the thread count. Fronts early in
// the order get low colours: the fronts a drawback puts first are served first.
#include <span>
#include <vector>

#include "engine/pyramids/fronts.hpp"

namespace tubemesh::pyramids {

class Batcher {
public:
    explicit Batcher(index_t front_count) : colour_(front_count, kNoIndex) {}

    // Batch c is out.row(c), fronts in the order given.
    void colour(std::span<const index_t> order, const Adjacency& neighbours, Adjacency& out);

private:
    std::vector<index_t> colour_;  // per front; kNoIndex outside the current call
    std::vector<index_t> seen_;    // per colour: the last front that saw it used (a stamp)
};

}  // namespace tubemesh::pyramids
