#pragma once
// Topological improvement moves on a TetDomain (paper §5, last sentences): the 2-3 flip of an
// inner face, and edge removal, which replaces the n tets around an inner edge by the 2n-4
// tets that join its two endpoints to the best triangulation of the ring of n points around it
// (n = 3 is the 3-2 flip, n = 4 the 4-4 flip). "Best" maximises the smallest tet collapse,
// found by dynamic programming over the ring polygon's triangulations (Shewchuk, "Two discrete
// optimization algorithms for the topological improvement of tetrahedral meshes").
//
// Planning only reads the domain; applying writes the planned tets into the old slots first,
// then into spare slots the caller hands over, and links them to the cavity's outside, so the
// caller decides where new tets go (the parallel pass gives each move its own slots).
// Front faces (kNoAdjacent) are never removed: a 2-3 flip needs a tet behind the face, and an
// edge whose shell meets the front is not removed; every other face on the cavity's boundary
// is kept as it is.
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/tets/domain/tet_domain.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {

// PointInsertion: a plan whose new tets join a new point to a cavity (point_insertion.hpp).
enum class FlipKind : std::uint8_t { Flip23, Flip32, Flip44, EdgeRemoval, PointInsertion };

struct FlipPlan {
    static constexpr int kMaxOld = EdgeShell::kMaxSize;
    static constexpr int kMaxNew = 2 * EdgeShell::kMaxSize - 4;
    FlipKind kind = FlipKind::Flip23;
    int old_count = 0, new_count = 0;
    std::array<index_t, kMaxOld> old_tets{};
    std::array<std::array<index_t, 4>, kMaxNew> new_tets{};  // positively oriented
    double old_min = 0;  // smallest collapse of the tets removed
    double new_min = 0;  // smallest collapse of the tets created
    double old_sum = 0, new_sum = 0;  // sums of the collapses of the tets removed and created

    // New slots the move needs beyond the ones it frees (negative when it frees one).
    int extra_slots() const { return new_count - old_count; }
};

// `slot_collapse` (optional, both planners): the collapse of the tet in every slot, as
// collapse_of over the slot's vertex row gives it; the planners read the old tets' collapses
// from it instead of computing them again (a sweep plans most tets many times over).

// The smallest collapse of `count` tets (slot ids) and, with `sum`, their sum in that order;
// read from slot_collapse when given: the old tets' figures of every plan.
double min_collapse_of_tets(const TetDomain& dom, const index_t* tets, int count, double* sum,
                            const double* slot_collapse = nullptr);

// Plans the 2-3 flip of face f of tet t (the face opposite vertex f). False when the face is a
// front face or the three new tets would not all be positively oriented (exact test). Also
// false when the new tets' smallest collapse is not above both must_exceed and the old tets'
// smallest collapse + gain (defaults: no such bound); the bound stops at the first new tet.
bool plan_flip23(const TetDomain& dom, index_t t, int f, FlipPlan& plan, const double* slot_collapse = nullptr,
                 double must_exceed = -std::numeric_limits<double>::infinity(),
                 double gain = -std::numeric_limits<double>::infinity());

// Plans the removal of the edge between local vertices la and lb of tet t, whose shell may
// hold at most max_ring tets (3..EdgeShell::kMaxSize). False when the shell is open or too
// large, or when no triangulation of the ring gives positively oriented tets (exact test).
// Also false when the best triangulation's smallest collapse is not above both must_exceed and
// the old tets' smallest collapse + gain (defaults: no such bound); the bound prunes the search.
bool plan_edge_removal(const TetDomain& dom, index_t t, int la, int lb, int max_ring, FlipPlan& plan,
                       double must_exceed = -std::numeric_limits<double>::infinity(),
                       double gain = -std::numeric_limits<double>::infinity(),
                       const double* slot_collapse = nullptr);

// The same for a closed shell edge_shell found (for callers that walk the shells themselves).
bool plan_shell_removal(const TetDomain& dom, const EdgeShell& shell, FlipPlan& plan,
                        double must_exceed = -std::numeric_limits<double>::infinity(),
                        double gain = -std::numeric_limits<double>::infinity(),
                        const double* slot_collapse = nullptr);

// Largest number of spare slots a plan with rings up to max_ring tets can need.
inline int max_extra_slots(int max_ring) { return max_ring - 4 > 1 ? max_ring - 4 : 1; }

// Replaces the plan's old tets by its new ones: old slots are reused first, then `spare`
// slots in order; old slots left over become free (vertex row kFreeSlot). Adjacency inside
// the new tets and to the tets around them (whose neighbour codes are updated) is rebuilt
// from shared faces. Returns how many spare slots were used. Throws tubemesh::Error when the
// plan does not fit the mesh (a face of the new tets matches nothing): a bug, never input.
int apply_flip(TetDomain& dom, const FlipPlan& plan, std::span<const index_t> spare);

// Serial convenience for tools and tests: applies the plan, appending slots at the end of the
// store as needed (free slots may remain; compact_tets removes them).
void apply_flip_appending(TetDomain& dom, const FlipPlan& plan);

// Removes free slots: live tets keep their relative order, neighbour codes are renumbered.
// `per_slot` (optional, one value per slot): compacted alike. In place (the live tets counted in
// parallel), so the optimisation never holds two stores.
void compact_tets(TetDomain& dom, std::vector<double>* per_slot = nullptr);

}  // namespace tubemesh::tets
