#include "batch/scheduler.hpp"

#include <algorithm>
#include <deque>
#include <map>

#include "batch/plan.hpp"
#include "batch/test_hooks.hpp"
#include "batch/worker.hpp"
#include "engine/core/timing.hpp"

namespace tubemesh::batch {

namespace {

// An estimate runs the import and the size plan only: a minute is far beyond what it needs.
constexpr double kEstimateTimeLimit = 600;
// A worker that dies is dealt its block once more.
constexpr int kAttempts = 2;

double time_limit(const BlockEntry& b) { return b.options.at("time_limit").get<double>(); }

// One estimate per block that has none yet, on every slot; stored in the catalogue.
void estimate_blocks(Executor& executor, Catalogue& catalogue, std::vector<PlannedBlock>& todo,
                     const std::function<void()>& tick, int interval_ms) {
    std::deque<std::size_t> queue;
    for (std::size_t i = 0; i < todo.size(); ++i)
        if (todo[i].estimate == 0) queue.push_back(i);
    while (!queue.empty() || executor.running() > 0) {
        while (!queue.empty() && executor.running() < static_cast<std::size_t>(executor.slots())) {
            const std::size_t i = queue.front();
            queue.pop_front();
            executor.start(i, estimate_request(*todo[i].block), kEstimateTimeLimit);
        }
        for (const WorkerOutcome& o : executor.wait(interval_ms)) {
            PlannedBlock& p = todo[o.tag];
            // A block that cannot be estimated goes last; meshing it will say what is wrong.
            p.estimate = o.result.value("status", "") == "done" ? o.result.value("estimate", -1.0) : -1.0;
            if (!(p.estimate > 0)) p.estimate = -1;
            catalogue.set_estimate(p.block->id, p.estimate);
        }
        if (tick) tick();
    }
}

}  // namespace

SlotPlan plan_slots(int threads, std::size_t blocks) {
    threads = std::max(1, threads);
    const int slots = static_cast<int>(std::clamp<std::size_t>(blocks, 1, static_cast<std::size_t>(threads)));
    return {slots, std::max(1, threads / slots)};
}

BatchSummary run_blocks(Executor& executor, Catalogue& catalogue, std::size_t total, std::vector<PlannedBlock> todo,
                        const BatchRun& run) {
    const auto t0 = Clock::now();
    fault_point("plan");

    BatchProgress progress;
    progress.total = static_cast<int>(total);
    progress.skipped = progress.total - static_cast<int>(todo.size());
    auto emit = [&](BatchProgress::Event e, const BlockEntry* block = nullptr, const BlockRecord* record = nullptr) {
        if (!run.progress) return;
        progress.event = e;
        progress.block = block;
        progress.record = record;
        progress.running = static_cast<int>(executor.running());
        progress.elapsed = seconds_since(t0);
        run.progress(progress);
    };
    emit(BatchProgress::Event::Planned);

    // Order matters only when blocks wait for one of several slots.
    if (executor.slots() > 1 && todo.size() > static_cast<std::size_t>(executor.slots())) {
        emit(BatchProgress::Event::Estimating);
        estimate_blocks(executor, catalogue, todo, [&] { emit(BatchProgress::Event::Tick); }, run.progress_interval_ms);
        order_largest_first(todo);
    }

    struct Job {
        const BlockEntry* block;
        int attempt;
    };
    std::deque<Job> queue;
    for (const PlannedBlock& p : todo) queue.push_back({p.block, 1});
    std::map<std::uint64_t, Job> running;
    std::uint64_t next_tag = 0;
    while (!queue.empty() || !running.empty()) {
        while (!queue.empty() && running.size() < static_cast<std::size_t>(executor.slots())) {
            const Job job = queue.front();
            queue.pop_front();
            executor.start(next_tag, mesh_request(*job.block, run.outdir, executor.threads(), job.attempt),
                           time_limit(*job.block));
            running[next_tag++] = job;
            emit(BatchProgress::Event::Started, job.block);
        }
        const std::vector<WorkerOutcome> ended = executor.wait(run.progress ? run.progress_interval_ms : -1);
        for (const WorkerOutcome& o : ended) {
            const Job job = running.at(o.tag);
            running.erase(o.tag);
            nlohmann::json result = o.result;
            if (result.value("status", "") == "crashed") {
                if (job.attempt < kAttempts) {
                    queue.push_front({job.block, job.attempt + 1});
                    emit(BatchProgress::Event::Retried, job.block);
                    continue;
                }
                result["status"] = "failed";
                result["error"] = result.value("error", "") + " (on each of " + std::to_string(kAttempts) + " attempts)";
            }
            BlockRecord record = record_from_result(*job.block, result);
            if (const auto old = catalogue.get(job.block->id)) record.estimate = old->estimate;
            catalogue.put(record);
            fault_point("recorded");
            if (record.status == "done") {
                ++progress.done;
                progress.elements += record.elements();
            } else {
                ++progress.failed;
            }
            emit(BatchProgress::Event::Finished, job.block, &record);
        }
        if (ended.empty()) emit(BatchProgress::Event::Tick);
    }

    BatchSummary s;
    s.total = progress.total;
    s.skipped = progress.skipped;
    s.done = progress.done;
    s.failed = progress.failed;
    s.elements = progress.elements;
    s.seconds = seconds_since(t0);
    return s;
}

}  // namespace tubemesh::batch
