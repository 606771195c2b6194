#include "engine/pyramids/advancing_front.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace tubemesh::pyramids {

namespace {

std::string where(const Vec3& p) {
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

// Every front of `fronts` is one of `among`.
bool all_in(std::vector<index_t> fronts, std::vector<index_t> among) {
    std::sort(fronts.begin(), fronts.end());
    std::sort(among.begin(), among.end());
    return std::includes(among.begin(), among.end(), fronts.begin(), fronts.end());
}

}  // namespace

AdvancingFront::AdvancingFront(const World& world, FrontState& state, const PyramidOptions& opt, PyramidStats& stats,
                               double sweep_size)
    : world_(world),
      state_(state),
      opt_(opt),
      stats_(stats),
      sweep_size_(sweep_size),
      batcher_(static_cast<index_t>(world.fronts.size())),
      choice_(world.fronts.size()) {}

// Normal pass over the active fronts, relaxed pass over those it rejected; fronts still
// rejected get a drawback and go first, squeezed, in the next round (§4 Steps 1-8).
void AdvancingFront::run() {
    std::vector<index_t> first;
    std::vector<index_t> active(world_.fronts.size());
    for (std::size_t i = 0; i < active.size(); ++i) active[i] = static_cast<index_t>(i);
    for (int round = 0;; ++round) {
        std::vector<index_t> still;
        if (!first.empty()) still = pass(first, Pass::Squeezed);
        const std::vector<index_t> rejected = pass(active, Pass::Normal);
        stats_.rejected += static_cast<index_t>(rejected.size());
        const std::vector<index_t> relaxed = pass(rejected, Pass::Relaxed);
        still.insert(still.end(), relaxed.begin(), relaxed.end());
        stats_.rejected_relaxed += static_cast<index_t>(still.size());
        if (still.empty()) return;
        if (round == opt_.max_drawback_rounds) fail(still, round);
        const std::vector<index_t> freed = draw_back(still);
        // Nothing to free around fronts that were squeezed already: another round would
        // repeat this one. Otherwise the next round squeezes them, even with nothing freed,
        // since only the squeezed pass moves try nodes off the faces (candidates.hpp).
        if (freed.empty() && all_in(still, first)) fail(still, round);
        if (!freed.empty()) ++stats_.drawback_rounds;
        stats_.drawback_deleted += static_cast<index_t>(freed.size());
        first = still;
        active = freed;
    }
}

Tally AdvancingFront::tally() const {
    Tally sum;
    for (const Tally& t : tallies_)
        for (int v = 0; v < kVerdictCount; ++v) sum.verdicts[v] += t.verdicts[v];
    return sum;
}

// Serves the fronts batch by batch; returns those that found no apex, in `order`'s order.
std::vector<index_t> AdvancingFront::pass(const std::vector<index_t>& order, Pass kind) {
    batcher_.colour(order, world_.neighbours, batches_);
    const index_t count = static_cast<index_t>(batches_.offset.size() - 1);
    for (index_t b = 0; b < count; ++b) {
        beat(opt_.pulse);
        const std::span<const index_t> batch = batches_.row(b);
        note_batch(static_cast<index_t>(batch.size()));
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 4),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              Visible& vis = scratch_.local();
                              Tally& tally = tallies_.local();
                              for (std::size_t k = r.begin(); k != r.end(); ++k)
                                  choice_[batch[k]] = serve_front(world_, batch[k], kind, opt_, vis, tally);
                          });
        // Commit in batch order: new apexes get their ids in a fixed order.
        for (index_t i : batch)
            if (choice_[i].found) state_.add_pyramid(i, choice_[i]);
    }
    std::vector<index_t> rejected;
    for (index_t i : order)
        if (!choice_[i].found) rejected.push_back(i);
    return rejected;
}

// Deletes the pyramids that reach into a rejected front's query ball; returns their
// fronts, ascending.
std::vector<index_t> AdvancingFront::draw_back(const std::vector<index_t>& rejected) {
    std::vector<index_t> freed;
    for (index_t i : rejected) {
        const Front& f = world_.fronts[i];
        const double r2 = f.query_radius * f.query_radius;
        for (index_t j : world_.neighbours.row(i)) {
            if (!state_.has_pyramid(j)) continue;
            bool near = distance2(state_.point(state_.apex(j)), f.ideal) < r2;
            for (const Vec3& c : world_.fronts[j].corner) near = near || distance2(c, f.ideal) < r2;
            if (!near) continue;
            state_.remove_pyramid(j);
            freed.push_back(j);
        }
    }
    std::sort(freed.begin(), freed.end());
    return freed;
}

std::string AdvancingFront::advice() const {
    if (!(sweep_size_ > 0)) return "lower the sweep size St";
    // The quads' edges, and the room they need, shrink with St; half leaves the room the criteria ask
    // for in front of a ring that missed it by up to about half its thickness.
    char s[160];
    std::snprintf(s, sizeof s, "the rings are St = %.6g thick here; lower it, to --sweep-size %.3g for a start,",
                  sweep_size_, 0.5 * sweep_size_);
    return s;
}

void AdvancingFront::fail(const std::vector<index_t>& still, int round) const {
    const index_t first = still.front();
    const Front& f = world_.fronts[first];
    // Where all of them are: a ring too close to its neighbour fails along its whole length,
    // and the first quad alone would point at one end of it.
    Box extent = Box::of(f.centroid);
    for (index_t i : still) extent.add(world_.fronts[i].centroid);
    std::vector<index_t> fronts = still;
    std::sort(fronts.begin(), fronts.end());
    throw PyramidRoomError("pyramids: " + std::to_string(still.size()) + " front quad(s) found no valid pyramid after " +
                std::to_string(round) + " drawback round(s), their centres between " + where(extent.lo) + " and " +
                where(extent.hi) + "; the first is quad " + std::to_string(first) + " near " + where(f.centroid) +
                " with edge length " + std::to_string(f.h) + ", whose last try node was refused as " +
                verdict_name(choice_[first].refusal) +
                ". A ring there is too close to another ring or to a face for its quad size (the criteria need "
                "about 1.2 edge lengths of room in front of a quad)", advice() + " or move the pipe",
                std::move(fronts));
}

void AdvancingFront::note_batch(index_t size) {
    stats_.batch_min = stats_.batches == 0 ? size : std::min(stats_.batch_min, size);
    stats_.batch_max = std::max(stats_.batch_max, size);
    stats_.batch_mean += size;
    ++stats_.batches;
}

}  // namespace tubemesh::pyramids
