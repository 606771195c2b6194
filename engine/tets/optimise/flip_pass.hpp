#pragma once
// One sweep of topological improvement over a whole TetDomain: every tet below a collapse
// threshold, worst first, gets the flip (2-3 on one of its faces, or removal of one of its
// edges) that best raises the smallest collapse of the tets it replaces; a tet at or above
// `mean_floor` instead gets the one that most raises the mesh's mean collapse (the new tets'
// sum minus the old ones' beyond `mean` per added tet) with every new tet at or above the floor.
//
// Parallel and deterministic. Planning a candidate reads its tet, the tet's face neighbours
// and the shells of its six edges; a plan depends only on its old tets (their vertex rows and
// collapses), and applying it writes only the old tets, their face neighbours' codes (the two
// are its claims) and the spare slots reserved for it. Each round plans, in parallel, every
// candidate without a plan or whose plan lost an old tet to a flip since (a candidate with no
// improving flip is dropped: later passes come back to it if something near it changes), then
// takes, in worst-first order, the candidates whose claims meet none taken before in the
// round, and applies them with tbb::parallel_for, each writing its new tets into slots
// reserved for it in that order; the others wait with their plans.
#include <cstdint>
#include <vector>

#include "engine/core/pulse.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct FlipSweepCounts {
    std::uint64_t flips23 = 0, flips32 = 0, flips44 = 0, edge_removals = 0;
    std::uint64_t rounds = 0;
    std::uint64_t total() const { return flips23 + flips32 + flips44 + edge_removals; }
};

// `mean`: the mesh's mean collapse now (0: no mean-raising flips). `active` (one flag per point,
// or nullptr for all points): only tets with an active vertex are attacked; later passes use it
// to revisit only what changed. Every vertex of a tet a
// flip creates gets changed[p] = 1 (changed has one flag per point). `collapses` (optional):
// on entry the collapse of every tet of dom when the caller has them (another size: computed
// here), on return the collapse of every tet of the result. Leaves no free slots.
FlipSweepCounts flip_sweep(TetDomain& dom, double threshold, double min_gain, int max_edge_ring, double mean,
                           double mean_floor, const std::vector<std::uint8_t>* active,
                           std::vector<std::uint8_t>& changed, std::vector<double>* collapses = nullptr,
                           const Pulse& pulse = {});

}  // namespace tubemesh::tets
