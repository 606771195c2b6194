#include "tools/mpi/mpi_executor.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "tools/mpi/mpi_messages.hpp"

namespace tubemesh::mpi {

namespace {

// The worker's pid with the rank it ran on, for the catalogue's "worker" column.
nlohmann::json on_rank(nlohmann::json result, int rank) {
    result["worker"] = "rank " + std::to_string(rank) + " " + result.value("worker", "");
    return result;
}

}  // namespace

int node_share_of_cores() {
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int on_node = 1;
    MPI_Comm_size(node, &on_node);
    MPI_Comm_free(&node);
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / std::max(1, on_node));
}

MpiExecutor::MpiExecutor(batch::WorkerCommand command, int ranks, int threads)
    : local_(std::move(command)), ranks_(ranks), threads_(threads) {}

void MpiExecutor::start(std::uint64_t tag, const nlohmann::json& request, double time_limit) {
    if (local_.running() == 0) {
        local_.start(tag, request, time_limit);
        return;
    }
    for (int rank = 1; rank < ranks_; ++rank)
        if (!busy_.count(rank)) {
            send_json({{"tag", tag}, {"time_limit", time_limit}, {"request", request}}, rank, kDeal);
            busy_.insert(rank);
            return;
        }
}

std::vector<batch::WorkerOutcome> MpiExecutor::wait(int timeout_ms) {
    using Clock = std::chrono::steady_clock;
    const auto until = timeout_ms < 0 ? Clock::time_point::max() : Clock::now() + std::chrono::milliseconds(timeout_ms);
    for (;;) {
        std::vector<batch::WorkerOutcome> ended = local_.wait(local_.running() > 0 ? 5 : 0);
        for (batch::WorkerOutcome& o : ended) o.result = on_rank(std::move(o.result), 0);
        while (auto r = try_receive(kResult)) {
            busy_.erase(r->from);
            ended.push_back({r->message.at("tag").get<std::uint64_t>(), on_rank(r->message.at("result"), r->from)});
        }
        if (!ended.empty() || running() == 0 || Clock::now() >= until) return ended;
        if (local_.running() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

void stop_ranks(int ranks) {
    for (int rank = 1; rank < ranks; ++rank) send_json(nullptr, rank, kStop);
}

void serve_rank(const batch::WorkerCommand& command) {
    batch::WorkerPool pool(command);
    for (;;) {
        const Received r = receive_any();
        if (r.tag == kStop) return;
        if (r.tag != kDeal) continue;
        pool.start(r.message.at("tag").get<std::uint64_t>(), r.message.at("request"),
                   r.message.at("time_limit").get<double>());
        std::vector<batch::WorkerOutcome> ended;
        while (ended.empty()) ended = pool.wait(-1);
        send_json({{"tag", ended.front().tag}, {"result", ended.front().result}}, 0, kResult);
    }
}

}  // namespace tubemesh::mpi
