#pragma once
// The messages between rank 0 (the dealer) and the worker ranks: JSON text on three tags.
//   kDeal    rank 0 -> worker  {"tag": n, "time_limit": s, "request": {...}} (batch/worker.hpp)
//   kResult  worker -> rank 0  {"tag": n, "result": {...}}
//   kStop    rank 0 -> worker  empty: no more blocks
#include <mpi.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace tubemesh::mpi {

inline constexpr int kDeal = 1, kResult = 2, kStop = 3;

void send_json(const nlohmann::json& message, int to, int tag);

// A message that has arrived from anyone on `tag`, or nothing; never blocks.
struct Received {
    int from = 0;
    int tag = 0;
    nlohmann::json message;
};
std::optional<Received> try_receive(int tag);

// Waits for a message on any tag without spinning a core (Open MPI's blocking receive
// busy-waits, which would take a core from the meshing process beside it).
Received receive_any();

}  // namespace tubemesh::mpi
