#pragma once
// Worker processes run side by side, each with its request, result pipe and time limit
// (batch/worker.hpp has the protocol). A worker is a fresh process per request: a fault or a
// leak in one block never reaches the next. Workers die with the process that started them
// (PR_SET_PDEATHSIG), so a killed batch leaves no meshing orphans behind.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/types.h>
#include <vector>

namespace tubemesh::batch {

// The program and arguments that start a worker: `tubemesh batch-worker`, say.
struct WorkerCommand {
    std::string program;
    std::vector<std::string> args;
};

// A finished request: the worker's result, or {"status": "failed", "error": ...,
// "timed_out": true} when the time limit ended it, or {"status": "crashed", "error": ...}
// when it died without a result (a signal, an exit without a result).
struct WorkerOutcome {
    std::uint64_t tag = 0;
    nlohmann::json result;
};

class WorkerPool {
public:
    explicit WorkerPool(WorkerCommand command);
    ~WorkerPool();  // kills the workers still running
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // Starts a worker on `request`; `time_limit` in seconds, 0 for none. Throws
    // tubemesh::Error when no process can be started.
    void start(std::uint64_t tag, const nlohmann::json& request, double time_limit);
    std::size_t running() const;
    // Waits at most `timeout_ms` (-1: until one ends) and returns the requests that ended.
    std::vector<WorkerOutcome> wait(int timeout_ms);

    struct Worker;  // one running request (worker_pool.cpp)

private:
    WorkerCommand command_;
    std::vector<Worker> workers_;
};

}  // namespace tubemesh::batch
