#pragma once
// One sweep of topological improvement over a whole TetDomain: every tet below a collapse
// threshold, worst first, gets the flip (2-3 on one of its faces, or removal of one of its
// edges) that best raises the smallest collapse of the tets it replaces.
//
// Parallel and deterministic: a move only touches tets that share a vertex with the tet it
// improves (the stars of its four vertices; every replaced tet and every tet whose neighbour
// code changes is there). Each round takes, in worst-first order, the candidates whose stars
// meet no star taken before in the round, and runs them with tbb::parallel_for, each writing
// its new tets into slots reserved for it in that order; the others wait for the next round.
#include <cstdint>

#include "engine/tets/tet_domain.hpp"

namespace tubemesh::tets {

struct FlipSweepCounts {
    std::uint64_t flips23 = 0, flips32 = 0, flips44 = 0, edge_removals = 0;
    std::uint64_t rounds = 0;
    std::uint64_t total() const { return flips23 + flips32 + flips44 + edge_removals; }
};

// Leaves no free slots behind.
FlipSweepCounts flip_sweep(TetDomain& dom, double threshold, double min_gain, int max_edge_ring);

}  // namespace tubemesh::tets
