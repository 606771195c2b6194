#pragma once
// The worker protocol: a block runs in its own process, so that a fault inside a library
// (OpenCASCADE on a malformed file) or a hang costs that block only. The batch process writes
// one request (JSON) to the worker's stdin; the worker writes one result (JSON) to file
// descriptor 3 and exits 0. A worker that dies or is killed writes no result.
//
//   request  {"mode": "mesh" | "estimate", "id", "cad" | "spec_text" + "spec_source",
//             "options" (resolved), "threads", "outputs": [paths], "report": path, "attempt"}
//   result   {"status": "done" | "failed", "error", "estimate", "nodes", "hexes", "pyramids",
//             "tets", "quality", "phases": [[name, seconds]], "seconds",
//             "outputs": [{"path", "bytes", "sha256"}], "report", "worker"}
//
// A block's files are `<id>.<format>` and `<id>.report.json` in the output folder, written
// all or none under their final names (job/outputs.hpp).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "batch/catalogue.hpp"
#include "batch/manifest.hpp"

namespace tubemesh::batch {

// The file descriptor the result goes to.
inline constexpr int kResultFd = 3;

nlohmann::json mesh_request(const BlockEntry& block, const std::filesystem::path& outdir, int threads, int attempt);
nlohmann::json estimate_request(const BlockEntry& block);

// Runs a request in this process: the result, "failed" with the error's one line when the
// block cannot be meshed. Throws nothing but what a library fault raises.
nlohmann::json run_request(const nlohmann::json& request);

// A worker process's whole life: reads the request from stdin, runs it, writes the result to
// kResultFd. Returns the exit code.
int worker_main();

// The catalogue row a finished block's result makes.
BlockRecord record_from_result(const BlockEntry& block, const nlohmann::json& result);

}  // namespace tubemesh::batch
