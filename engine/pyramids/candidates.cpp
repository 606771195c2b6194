#include "engine/pyramids/candidates.hpp"

#include <cmath>

#include "engine/pyramids/criteria.hpp"

namespace tubemesh::pyramids {

namespace {

// Judges one candidate and counts the verdict; fills `choice` when accepted and keeps the
// refusal of a new node for the error message when none is.
bool try_candidate(const Front& f, const Candidate& c, const Thresholds& t, std::uint8_t how, const Visible& vis,
                   const FrontState& state, Tally& tally, Choice& choice) {
    const Verdict v = judge(f, c, t, vis, state);
    if (c.id == kNoIndex) choice.refusal = v;
    ++tally.verdicts[static_cast<int>(v)];
    if (v != Verdict::Accepted) return false;
    choice = {true, c.id, c.p, how, Verdict::Accepted};
    return true;
}

bool try_existing(const Front& f, const Thresholds& t, std::uint8_t how, const Visible& vis, const FrontState& state,
                  Tally& tally, Choice& choice) {
    for (const NearNode& n : vis.candidates)
        if (try_candidate(f, {n.id, n.p}, t, how, vis, state, tally, choice)) return true;
    return false;
}

// What the candidate pyramid on f with a new apex at p can fail on (visible.hpp).
Focus focus_on(const Front& f, const Vec3& p, const Thresholds& t) {
    Focus focus{false, Box::of(p), t.min_distance2};
    for (const Vec3& c : f.corner) focus.box.add(c);
    return focus;
}

// The try node at Rate: Rate of the way from M to N (on the normal line but for a front
// placed for a wedge, fronts.hpp).
Vec3 try_node(const Front& f, double rate) {
    return (f.centroid + rate * f.shift) + (f.height * rate) * f.normal;
}

}  // namespace

Choice serve_front(const World& world, index_t front, Pass pass, const PyramidOptions& opt, Visible& vis,
                   Tally& tally) {
    const Front& f = world.fronts[front];
    Choice choice;
    if (pass == Pass::Normal) {
        const Thresholds t = Thresholds::at(f, opt, 1.0);
        // The ideal apex, usually taken, on what can fail it alone; then everything.
        gather_visible(world, front, vis, focus_on(f, f.ideal, t));
        if (try_candidate(f, {kNoIndex, f.ideal}, t, kHowIdeal, vis, world.state, tally, choice)) return choice;
        gather_visible(world, front, vis);
        if (has_wide(f) && try_candidate(f, {kNoIndex, f.wide}, t, kHowWide, vis, world.state, tally, choice))
            return choice;
        try_existing(f, t, kHowExisting, vis, world.state, tally, choice);
        return choice;
    }
    gather_visible(world, front, vis);
    for (int step = 0; step < opt.try_nodes; ++step) {
        const int k = pass == Pass::Relaxed ? step + 1 : opt.try_nodes - step;
        const double rate = std::pow(opt.relax_rate, k);
        const Thresholds t = Thresholds::at(f, opt, rate);
        const Vec3 node = try_node(f, rate);
        const auto how = static_cast<std::uint8_t>(kHowTryBase + k - 1);
        if (try_candidate(f, {kNoIndex, node}, t, how, vis, world.state, tally, choice)) return choice;
        if (try_existing(f, t, kHowExistingRelaxed, vis, world.state, tally, choice)) return choice;
    }
    // Squeezed and still none of the paper's candidates fits: the try nodes moved off the
    // faces they are too close to (criteria.hpp, move_off_faces), largest first. Only here,
    // after a drawback: where the neighbours' pyramids are what is in the way, the drawback
    // gives better pyramids than a tilted apex would.
    if (pass != Pass::Squeezed) return choice;
    const Verdict refusal = choice.refusal;
    for (int k = 1; k <= opt.try_nodes; ++k) {
        const double rate = std::pow(opt.relax_rate, k);
        const Thresholds t = Thresholds::at(f, opt, rate);
        Vec3 node = try_node(f, rate);
        if (!move_off_faces(f, t, vis, node)) continue;
        const auto how = static_cast<std::uint8_t>(kHowMovedTryBase + k - 1);
        if (try_candidate(f, {kNoIndex, node}, t, how, vis, world.state, tally, choice)) return choice;
    }
    choice.refusal = refusal;  // the error message names what stopped the paper's try nodes
    return choice;
}

}  // namespace tubemesh::pyramids
