#pragma once
// Which blocks a run still has to mesh, and in which order.
#include <filesystem>
#include <vector>

#include "batch/catalogue.hpp"
#include "batch/manifest.hpp"

namespace tubemesh::batch {

// Shard `shard` of `shards` (Slurm array task I of N): the blocks whose manifest position is
// I modulo N; every block when shards is 0. The same manifest always gives the same shares.
std::vector<const BlockEntry*> shard_blocks(const Manifest& manifest, int shard, int shards);

// True when the block's row is done for its current input and options, and every file the
// row names is in `outdir` with the size it had.
bool done_and_intact(const BlockRecord& row, const BlockEntry& block, const std::filesystem::path& outdir);

struct PlannedBlock {
    const BlockEntry* block = nullptr;
    double estimate = 0;  // from the catalogue when input and options are unchanged; 0: unknown
};

// Brings the catalogue in line with `blocks` in one transaction: a done and intact block keeps
// its row, every other one gets a pending row (its estimate kept when the hashes match), and
// rows of blocks not listed go. Returns the blocks still to mesh, in manifest order.
std::vector<PlannedBlock> plan_run(Catalogue& catalogue, const std::vector<const BlockEntry*>& blocks,
                                   const std::filesystem::path& outdir);

// Largest estimate first (unknown ones last), then manifest order.
void order_largest_first(std::vector<PlannedBlock>& blocks);

}  // namespace tubemesh::batch
