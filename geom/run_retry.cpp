#include "geom/run_retry.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace tubemesh::geom {

namespace {

std::string tube_list(const std::vector<std::size_t>& tubes) {
    std::string s = tubes.size() == 1 ? "tube " : "tubes ";
    for (std::size_t i = 0; i < tubes.size(); ++i) s += (i ? ", " : "") + std::to_string(tubes[i] + 1);
    return s;
}

}  // namespace

RunRetry::RunRetry(const MeshOptions& options)
    : options_(options),
      // A St from the user or the caller's own per-tube list is kept as given.
      sweep_given_(options.sweep_size > 0 || options.sweep.sweep_size > 0 || !options.sweep.tube_sweep_size.empty()),
      chordal_first_(options.chordal) {}

PrepareOptions RunRetry::prepare_options() const {
    PrepareOptions p = geom::prepare_options(options_);
    p.discretize.tube_sweep_size = options_.sweep.tube_sweep_size;
    p.drop = dropped_;
    return p;
}

void RunRetry::after(const RetryableFailure& failure, const PreparedModel& prepared) {
    const SizePlan& plan = prepared.plan;
    const std::size_t tube_count = prepared.geometry.tubes.size();
    if (failure.cause == RetryableFailure::Cause::PyramidRoom) {
        const double st = sweep_given_ && options_.sweep_size > 0 ? options_.sweep_size : plan.sweep_size;
        if (sweep_given_)
            throw Error(fmt::format("{} (St = {:.6g} was given: try --sweep-size {:.6g}, or leave St out to let "
                                    "tubemesh thin the rings that lack room)",
                                    failure.finding, st, kSweepFactor * st));
        // The engine's advice names the first attempt's St: the retry's own replaces it.
        if (!room_failure_) room_failure_ = failure.finding;
        plan_sweep_ = plan.sweep_size;
        std::vector<double>& sizes = options_.sweep.tube_sweep_size;
        sizes.resize(tube_count, 0.0);
        sweep_steps_.resize(tube_count, 0);
        // No tube named (a front outside every ring): every ring is thinned.
        std::vector<index_t> tubes = failure.tubes;
        if (tubes.empty())
            for (std::size_t t = 0; t < tube_count; ++t) tubes.push_back(static_cast<index_t>(t));
        // Last first: a tube that loses its ring shifts the ones after it down by one.
        for (auto it = tubes.rbegin(); it != tubes.rend(); ++it) {
            const index_t t = *it;
            if (t >= tube_count) throw Error(failure.what());
            if (sweep_steps_[t] < kSweepSteps) {
                sizes[t] = kSweepFactor * (sizes[t] > 0 ? sizes[t] : plan_sweep_);
                ++sweep_steps_[t];
                continue;
            }
            // The failure names no tube when no ring holds the front: nothing to drop then. Thin
            // rings facing each other can leave their pyramids no room at any St: the paper's one
            // St, cut for the closest place of all, is the last resort.
            if (failure.tubes.empty() && options_.local_ring) {
                options_.local_ring = false;
                global_fallback_ = true;
                sizes.assign(tube_count, 0.0);
                sweep_steps_.assign(tube_count, 0);
                return;
            }
            if (failure.tubes.empty())
                throw Error(fmt::format("{} (the rings were thinned to St = {:.6g} without success: move the pipes "
                                        "or give a larger --size)",
                                        *room_failure_, sizes[t]));
            std::vector<int> faces(prepared.geometry.tubes[t].wall_faces.begin(),
                                   prepared.geometry.tubes[t].wall_faces.end());
            std::sort(faces.begin(), faces.end());  // as TubeInfo::faces, which prepare matches
            std::string list;
            for (int f : faces) list += (list.empty() ? "" : ", ") + std::to_string(f);
            dropped_.push_back(
                {faces, 0, 0, fmt::format("its pyramids found no room down to St = {:.3g}", sizes[t]),
                 fmt::format("{} in front of the ring of the pipe of wall face{} {}, thinned {} times down to St = "
                             "{:.6g}: no hex ring, meshed with tetrahedra; for a hex ring, move the pipe or give a "
                             "larger --size",
                             *room_failure_, faces.size() == 1 ? "" : "s", list, kSweepSteps, sizes[t]),
                 false, prepared.splits});
            sizes.erase(sizes.begin() + t);
            sweep_steps_.erase(sweep_steps_.begin() + t);
        }
        return;
    }
    if (!chordal_failure_) chordal_failure_ = failure.what();
    if (chordal_steps_ == kChordalSteps) {
        if (options_.chordal_given)
            throw Error(fmt::format("{} at --chordal {:.6g}, the tolerance given, and at coarser ones up to {:.6g}: "
                                    "give another --size or --chordal",
                                    *chordal_failure_, chordal_first_, options_.chordal));
        throw Error(fmt::format("{} at chordal tolerances from {:.6g} to {:.6g}: give another --size or --chordal",
                                *chordal_failure_, chordal_first_, options_.chordal));
    }
    options_.chordal *= kChordalFactor;
    ++chordal_steps_;
}

void RunRetry::accept() const {
    if (chordal_steps_ > 0 && options_.chordal_given)
        throw Error(fmt::format("{} at --chordal {:.6g}, the tolerance given; --chordal {:.6g} meshes this model",
                                *chordal_failure_, chordal_first_, options_.chordal));
}

std::vector<std::string> RunRetry::warnings() const {
    std::vector<std::string> w;
    std::vector<std::size_t> thinned;
    for (std::size_t t = 0; t < sweep_steps_.size(); ++t)
        if (sweep_steps_[t] > 0) thinned.push_back(t);
    if (!thinned.empty()) {
        std::string sizes;
        for (std::size_t t : thinned)
            sizes += fmt::format("{}St = {:.6g} for tube {}", sizes.empty() ? "" : ", ", options_.sweep.tube_sweep_size[t],
                                 t + 1);
        w.push_back(fmt::format("the pyramids found no room in front of the ring{} of {} at St = {:.6g}: meshed with "
                                "{} (the other rings keep St = {:.6g}; give --sweep-size to choose St yourself)",
                                thinned.size() == 1 ? "" : "s", tube_list(thinned), plan_sweep_, sizes, plan_sweep_));
    }
    if (global_fallback_)
        w.push_back(fmt::format("the pyramids found no room in front of the locally thinned rings at any St: meshed "
                                "with one St for every ring, cut by the paper's rules (as --global-ring)"));
    if (chordal_steps_ > 0)
        w.push_back(fmt::format("boundary recovery gave up at chordal tolerance {:.6g} on a valid front: meshed with "
                                "--chordal {:.6g} (curved edges cut coarser)",
                                chordal_first_, options_.chordal));
    return w;
}

std::string RunRetry::ring_reason(std::size_t t) const {
    if (t >= sweep_steps_.size() || sweep_steps_[t] == 0) return {};
    return fmt::format("its pyramids found no room at St = {:.6g}: thinned to {:.6g}", plan_sweep_,
                       options_.sweep.tube_sweep_size[t]);
}

std::vector<std::string> RunRetry::report_lines() const {
    std::vector<std::string> lines;
    for (std::size_t t = 0; t < sweep_steps_.size(); ++t)
        if (sweep_steps_[t] > 0)
            lines.push_back(fmt::format("  retry: tube {}: St {:.6g} -> {:.6g}: its pyramids found no room", t + 1,
                                        plan_sweep_, options_.sweep.tube_sweep_size[t]));
    if (global_fallback_) lines.push_back("  retry: the local ring's pyramids found no room: one St for every ring");
    if (chordal_steps_ > 0)
        lines.push_back(fmt::format("  retry: chordal {:.6g} -> {:.6g}: boundary recovery gave up", chordal_first_,
                                    options_.chordal));
    return lines;
}

}  // namespace tubemesh::geom
