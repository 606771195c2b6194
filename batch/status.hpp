#pragma once
// What `tubemesh batch --status` and `--csv` show of a catalogue.
#include <string>
#include <vector>

#include "batch/catalogue.hpp"

namespace tubemesh::batch {

// Counts (done, failed, pending), elements and elements per second of block time, the worst
// quality of each kind and the block it is in, and every failed block's error.
std::string status_text(const std::vector<BlockRecord>& rows);

// One row per block (RFC 4180): id, status, error, hashes, counts, quality, seconds, one
// column per phase's seconds, and the output files with their SHA-256.
std::string status_csv(const std::vector<BlockRecord>& rows);

}  // namespace tubemesh::batch
