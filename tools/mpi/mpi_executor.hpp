#pragma once
// The batch's executor across MPI ranks, on rank 0: one slot on rank 0 itself (a worker
// process beside the dealer) and one per other rank. Each rank runs its block in a worker
// process of its own (batch/worker_pool.hpp), so a block that faults or hangs costs that block,
// and the rank lives on to take the next; the scheduler deals a dead worker's block again.
#include <map>
#include <set>

#include "batch/scheduler.hpp"
#include "batch/worker_pool.hpp"

namespace tubemesh::mpi {

class MpiExecutor : public batch::Executor {
public:
    // `threads`: per block (every rank gives its blocks this many).
    MpiExecutor(batch::WorkerCommand command, int ranks, int threads);
    int slots() const override { return ranks_; }
    int threads() const override { return threads_; }
    void start(std::uint64_t tag, const nlohmann::json& request, double time_limit) override;
    std::size_t running() const override { return local_.running() + busy_.size(); }
    std::vector<batch::WorkerOutcome> wait(int timeout_ms) override;

private:
    batch::WorkerPool local_;
    int ranks_, threads_;
    std::set<int> busy_;  // ranks with a block
};

// A worker rank's life: runs what rank 0 deals until it says stop.
void serve_rank(const batch::WorkerCommand& command);

// Tells every other rank that there is nothing more to do (rank 0, at the end, error or not).
void stop_ranks(int ranks);

// Cores on this node over the ranks on it, at least 1: threads per block by default.
// Collective: every rank calls it.
int node_share_of_cores();

}  // namespace tubemesh::mpi
