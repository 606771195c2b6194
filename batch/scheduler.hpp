#pragma once
// Runs a batch's blocks on an executor (worker processes on this machine, or MPI ranks) and
// keeps the catalogue: the one scheduling loop every mode shares, so every mode meshes the
// same blocks with the same options and records them alike.
//
// Order: the plan (batch/plan.hpp, made by the caller), then, when blocks outnumber the
// executor's slots, one estimate per block whose estimate is not in the catalogue yet, then the
// blocks largest first. A block whose worker dies (signal, lost process) is dealt again once; a second death,
// an error or the time limit marks it failed with its one-line error. The catalogue gets one
// transaction per finished block, after the block's files are complete.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "batch/catalogue.hpp"
#include "batch/manifest.hpp"
#include "batch/plan.hpp"
#include "batch/worker_pool.hpp"

namespace tubemesh::batch {

// Where requests run. slots() at once, each on threads() threads.
class Executor {
public:
    virtual ~Executor() = default;
    virtual int slots() const = 0;
    virtual int threads() const = 0;
    virtual void start(std::uint64_t tag, const nlohmann::json& request, double time_limit) = 0;
    virtual std::size_t running() const = 0;
    virtual std::vector<WorkerOutcome> wait(int timeout_ms) = 0;
};

// Worker processes on this machine: `slots` side by side.
class LocalExecutor : public Executor {
public:
    LocalExecutor(WorkerCommand command, int slots, int threads) : pool_(std::move(command)), slots_(slots), threads_(threads) {}
    int slots() const override { return slots_; }
    int threads() const override { return threads_; }
    void start(std::uint64_t tag, const nlohmann::json& request, double time_limit) override {
        pool_.start(tag, request, time_limit);
    }
    std::size_t running() const override { return pool_.running(); }
    std::vector<WorkerOutcome> wait(int timeout_ms) override { return pool_.wait(timeout_ms); }

private:
    WorkerPool pool_;
    int slots_, threads_;
};

// Slots and threads per block for `threads` cores and `blocks` blocks: side by side with one
// thread each when blocks outnumber the cores, else one slot per block sharing the cores.
struct SlotPlan {
    int slots = 1, threads = 1;
};
SlotPlan plan_slots(int threads, std::size_t blocks);

struct BatchProgress {
    enum class Event { Planned, Estimating, Started, Retried, Finished, Tick };
    Event event = Event::Planned;
    const BlockRecord* record = nullptr;  // Finished: the block's new row
    const BlockEntry* block = nullptr;    // Started, Retried, Finished
    int total = 0;    // blocks of this run
    int skipped = 0;  // done before this run, unchanged
    int done = 0, failed = 0, running = 0;
    std::int64_t elements = 0;  // meshed by this run
    double elapsed = 0;         // seconds since the run started
};

struct BatchRun {
    std::filesystem::path outdir;
    std::function<void(const BatchProgress&)> progress;  // may be empty
    int progress_interval_ms = 1000;  // Planned/Finished events come anyway; this adds ticks
};

struct BatchSummary {
    int total = 0, skipped = 0, done = 0, failed = 0;
    std::int64_t elements = 0;
    double seconds = 0;
};

// `todo`: what plan_run (batch/plan.hpp) left to mesh of `total` blocks.
BatchSummary run_blocks(Executor& executor, Catalogue& catalogue, std::size_t total, std::vector<PlannedBlock> todo,
                        const BatchRun& run);

}  // namespace tubemesh::batch
