#pragma once
// Tet mesh optimisation, the last part of the tet step (paper §5), on a worklist of the tets
// below a quality threshold: first flips (2-3, 3-2, 4-4, edge removal) of the tets below
// flip_threshold, worst first, that raise the smallest tet collapse of the tets they replace,
// or (at or above mean_floor) the mesh's mean collapse; then smoothing of the free points of the
// tets below smoothing_threshold, which moves a point when the worst tet around it gets better,
// or (at or above mean_floor) when the sum of the collapses around it does. Later passes only
// revisit the worklist near what changed, and once a pass gains little on the mean only near
// the poorest tets; the heavier rescue (flip-and-move search, new points) runs last, on the
// few tets those could not lift. Flips and moves run in parallel on conflict-free sets chosen
// in a fixed order, so the result depends on the input only: the same arrays for any thread
// count and any timing.
//
// Invariants kept (tet_domain.hpp): every tet positively oriented (exact test), adjacency
// symmetric, front faces never removed or changed, front points [0, front_points) never moved,
// no free slots at the end. The tets still fill the same region, so the volume is unchanged.
// Points are only ever added (by the rescue, after the passes), never removed.
#include <cstdint>


#include "engine/core/pulse.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

struct OptimiseOptions {
    // Rounds of (flips, then smoothing); optimisation stops earlier when a round changes
    // nothing or gains little (min_mean_gain). After the first pass, flips and moves are only
    // tried near the points a flip or move changed since. Default 8.
    int passes = 8;
    // Flips attack the tets whose collapse is below this value, worst first. Default 0.5: a tet
    // above it is good enough that changing its neighbourhood risks more than it gains.
    double flip_threshold = 0.5;
    // A flip is made only when it raises the smallest collapse of the tets it replaces (or, at
    // or above mean_floor, the sum of the mesh's collapses) by more than this per old tet.
    // Default 1e-6: guards against endless flipping between equal configurations.
    double min_gain = 1e-6;
    // Largest number of tets around an edge that edge removal tries (3..10). Default 5: larger
    // rings change the meshes by a few 1e-5 of the mean and cost a fifth more flip time
    // (bench/results/tuning-notes.md). The worst-tet rescue still tries rings up to
    // EdgeShell::kMaxSize.
    int max_edge_ring = 5;
    // Smoothing sweeps per pass (the first over the free points near a change since the last
    // pass, every later one over the points near a move of the sweep before). Default 1: a
    // second sweep before the next flips raised the mean less than another pass does.
    int smoothing_sweeps = 1;
    // The smoothing's worklist: the free points of the tets below this collapse (a point whose
    // tets are all at or above it is not moved). Default 0.8: 1.0 (every free point, as the
    // optimisation once did) added 0.002 to the dam block's mean at S 0.3 for 0.26 s more CPU
    // time (the run's 3.57 s); 0.6 lost 0.005 of it, and 0.007-0.010 on paper-ex3 and the
    // economy paper-ex1, below their tet mean bars (bench/results/tuning-notes.md).
    double smoothing_threshold = 0.8;
    // A pass that raises the mean collapse by less than this fraction of it ends the passes over
    // the whole worklist; the remaining ones only work near the tets below 0.35 (the minimum's).
    // Default 0.02: on the serpentine lift the first pass gains 3 %, the next three 0.8, 0.3 and
    // 0.15 % (0.009 of the mean) for 1.6 times the first one's CPU time; 0.05 ends paper-ex1's
    // passes (economy preset) after the first, 0.004 lower.
    double min_mean_gain = 0.02;
    // Below this collapse, flips and moves raise the smallest collapse of what they change;
    // at or above it they raise the mesh's mean collapse and never make a tet below
    // min(its old worst, mean_floor). Default 0.40: a lower floor raises the mean a little more
    // but lets the lowest minimum fall (bench/results/tuning-notes.md).
    double mean_floor = 0.40;
    // After the passes, the tets below this, worst first, try every 2-3 flip and inner-edge
    // removal (rings up to 10) followed by moves of the new tets' free points, or when none
    // lifts one, a new free point over one of its faces (worst_tet_rescue.hpp), until one
    // nothing lifts (it then bounds the minimum); then one more flip sweep near them and one
    // smoothing sweep over all free points win back the mean. Default 0.32, above the 0.30
    // minimum the tet step aims for: the worst tets of the paper examples have four front
    // points, so no move reaches them and no single flip lifts them. 0: off.
    double rescue_below = 0.32;
};

struct OptimiseStats {
    index_t tets_before = 0, tets_after = 0;
    double min_collapse_before = 0, mean_collapse_before = 0;
    double min_collapse_after = 0, mean_collapse_after = 0;
    index_t below_threshold_before = 0, below_threshold_after = 0;  // tets under flip_threshold
    std::uint64_t flips23 = 0, flips32 = 0, flips44 = 0, edge_removals = 0;
    std::uint64_t flip_rounds = 0;  // conflict-free parallel rounds of flips
    std::uint64_t moves = 0;        // accepted point moves
    std::uint64_t colours = 0;      // largest number of point colours of a smoothing pass
    int passes = 0;                 // passes run
    std::uint64_t rescued = 0;      // tets lifted by the final flip-and-move search (rescue_below)
    std::uint64_t inserted_points = 0;  // of those, the ones lifted by a new free point
    double seconds_flips = 0, seconds_smoothing = 0, seconds_rescue = 0, seconds_total = 0;
};

// Throws tubemesh::Error on options out of range; a domain with free slots is compacted first.
// Runs in the caller's oneTBB arena; the result is the same for any thread count.
OptimiseStats optimise(TetDomain& domain, const OptimiseOptions& options = {}, const Pulse& pulse = {});

}  // namespace tubemesh::tets
