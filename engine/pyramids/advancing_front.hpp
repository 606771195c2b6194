#pragma once
// The advancing front of §4 as a sequence of passes: the normal pass over the active
// fronts, the relaxed pass over those it rejected, and for fronts rejected even then a
// drawback — their neighbours' pyramids are deleted, and the next round serves them first,
// squeezed (candidates.hpp), before the freed neighbours get the normal pass again. Each
// pass serves its fronts in conflict-free batches (batches.hpp): a batch is evaluated in
// parallel against the state it started from, then committed front by front in batch order.
#include <tbb/enumerable_thread_specific.h>

#include <string>
#include <vector>

#include "engine/pyramids/batches.hpp"
#include "engine/pyramids/build_pyramids.hpp"
#include "engine/pyramids/candidates.hpp"
#include "engine/pyramids/front_state.hpp"
#include "engine/pyramids/visible.hpp"

namespace tubemesh::pyramids {

class AdvancingFront {
public:
    // `state` is world.state, writable: only the commits between batches change it.
    // `sweep_size`: the rings' St, named in the failure's advice (0: not known).
    AdvancingFront(const World& world, FrontState& state, const PyramidOptions& opt, PyramidStats& stats,
                   double sweep_size = 0);

    // Puts a pyramid on every front, or throws tubemesh::Error naming the first front that
    // found none after opt.max_drawback_rounds drawbacks (or when a drawback frees nothing
    // around fronts that were squeezed already).
    void run();

    // Candidate verdicts over all threads.
    Tally tally() const;

private:
    std::vector<index_t> pass(const std::vector<index_t>& order, Pass kind);
    std::vector<index_t> draw_back(const std::vector<index_t>& rejected);
    std::string advice() const;  // what the failure message tells the user to change
    [[noreturn]] void fail(const std::vector<index_t>& still, int round) const;
    void note_batch(index_t size);

    const World& world_;
    FrontState& state_;
    const PyramidOptions& opt_;
    PyramidStats& stats_;
    double sweep_size_;
    Batcher batcher_;
    Adjacency batches_;
    std::vector<Choice> choice_;  // per front: the outcome of its latest evaluation
    tbb::enumerable_thread_specific<Visible> scratch_;
    tbb::enumerable_thread_specific<Tally> tallies_;
};

}  // namespace tubemesh::pyramids
