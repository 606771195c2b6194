#pragma once
// The candidate apexes of one front, in the order the paper tries them, and the first that
// passes the criteria.
//  * normal pass (§4 Step 4): the ideal node N, then the existing front nodes within the
//    candidate radius of N, nearest first;
//  * relaxed pass (§4 Step 8), for fronts the normal pass rejected: for k = 1..try_nodes,
//    the k-th try node M + Rate·(N − M) (M + height_factor·h·Rate·n but for a front placed
//    for a wedge, fronts.hpp), then the existing nodes, all judged at Rate = relax_rate^k.
//    The try nodes step down the line from N, where the usual
//    obstacle (a face or a neighbour's pyramid above the front) leaves more room, and their
//    height shrinks with the distance threshold so the two stay in proportion;
//  * squeezed pass, for fronts the relaxed pass rejected and a drawback has freed: the
//    relaxed candidates from k = try_nodes down to 1. With its neighbours' pyramids deleted
//    such a front would take a large apex again and starve them again; the smallest pyramid
//    that fits leaves them the most room.
//  * squeezed pass, when none of those fits either: the try nodes k = 1..try_nodes, each
//    moved off the faces it is too close to (criteria.hpp, move_off_faces). For a front that
//    the host face itself leaves no room on the normal line (an end quad under a host that
//    leans over it), which no drawback can change.
#include <array>
#include <cstdint>

#include "engine/pyramids/build_pyramids.hpp"
#include "engine/pyramids/front_state.hpp"
#include "engine/pyramids/visible.hpp"

namespace tubemesh::pyramids {

enum class Pass : std::uint8_t { Normal, Relaxed, Squeezed };

// Verdict counts of one thread; summed at the end (integer sums: order does not matter).
struct Tally {
    std::array<std::uint64_t, kVerdictCount> verdicts{};
};

Choice serve_front(const World& world, index_t front, Pass pass, const PyramidOptions& opt, Visible& scratch,
                   Tally& tally);

}  // namespace tubemesh::pyramids
