#pragma once
// The last resort for the few tets that decide the minimum: their four points are usually
// front points (paper-ex2: every tet below 0.33), so no move reaches them, and no single flip
// raises them either. A flip followed by moves of the free points of the tets it makes
// often does: the flip brings a free point into the bad tet's place, the move then lifts it.
// Each tet below `bound` (OptimiseOptions::rescue_below), worst first, tries every 2-3 flip
// of its faces and every removal of its inner edges (rings up to EdgeShell::kMaxSize), each
// with up to 3 moves of every free point of the new tets towards the centroid of its star
// or the regular apex of one of its tets below the bound (steps 1 .. 1/16), and keeps the
// one that raises the smallest collapse of the tets it changes most. A tet no flip lifts tries
// a new free point instead (point_insertion.hpp), over each of its faces, followed by the same
// moves; the first tet nothing lifts ends the search. Serial and in (collapse, tet) order, so
// the result depends on the input only; a handful of tets per mesh, a few milliseconds.
#include <cstdint>
#include <vector>

#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct RescueCounts {
    std::uint64_t lifted = 0;    // tets lifted
    std::uint64_t inserted = 0;  // of those, by a new point
};

// `q`: every tet's collapse on entry, kept up to date while it works and compacted with the
// store at the end: on return q[t] is collapse_of of tet t's row, for every tet. Inserted points
// are appended to dom.xyz, and `changed` (one flag per point) grows with them; every point of a
// changed tet gets changed[p] = 1.
RescueCounts rescue_worst_tets(TetDomain& dom, double bound, std::vector<double>& q,
                               std::vector<std::uint8_t>& changed);

}  // namespace tubemesh::tets
