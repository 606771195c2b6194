#pragma once
// Which blocks a run still has to mesh, and in which order.
#include <filesystem>
#include <string>
#include <vector>

#include "batch/catalogue.hpp"
#include "batch/manifest.hpp"

namespace tubemesh::batch {

// Shard `shard` of `shards` (Slurm array task I of N): the blocks whose manifest position is
// I modulo N; every block when shards is 0. The same manifest always gives the same shares.
std::vector<const BlockEntry*> shard_blocks(const Manifest& manifest, int shard, int shards);

// What is wrong with the files a done row names in `outdir` ("c1-l2.msh changed since it was
// written": another size or SHA-256 than the catalogue holds, missing, unreadable), or empty when
// every one is as the worker wrote it. Reads every output through.
std::string changed_output(const BlockRecord& row, const std::filesystem::path& outdir);

// True when the block's row is done for its current input and options, and its files are intact.
bool done_and_intact(const BlockRecord& row, const BlockEntry& block, const std::filesystem::path& outdir);

// The catalogue's rows as the next run sees them: a done row whose files changed is pending,
// with what changed as its error.
void recheck_done_rows(std::vector<BlockRecord>& rows, const std::filesystem::path& outdir);

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
