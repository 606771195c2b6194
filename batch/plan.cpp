#include "batch/plan.hpp"

#include <algorithm>

namespace tubemesh::batch {

namespace fs = std::filesystem;

std::vector<const BlockEntry*> shard_blocks(const Manifest& manifest, int shard, int shards) {
    std::vector<const BlockEntry*> out;
    for (const BlockEntry& b : manifest.blocks)
        if (shards <= 0 || b.position % shards == shard) out.push_back(&b);
    return out;
}

bool done_and_intact(const BlockRecord& row, const BlockEntry& block, const fs::path& outdir) {
    if (row.status != "done" || row.input_hash != block.input_hash || row.options_hash != block.options_hash)
        return false;
    std::error_code ec;
    for (const OutputFile& f : row.outputs)
        if (fs::file_size(outdir / f.path, ec) != f.bytes || ec) return false;
    return fs::exists(outdir / row.report, ec);
}

std::vector<PlannedBlock> plan_run(Catalogue& catalogue, const std::vector<const BlockEntry*>& blocks,
                                   const fs::path& outdir) {
    std::vector<BlockRecord> rows;
    std::vector<PlannedBlock> todo;
    for (const BlockEntry* b : blocks) {
        const std::optional<BlockRecord> old = catalogue.get(b->id);
        if (old && done_and_intact(*old, *b, outdir)) {
            BlockRecord kept = *old;
            kept.position = b->position;
            rows.push_back(std::move(kept));
            continue;
        }
        BlockRecord pending;
        pending.id = b->id;
        pending.position = b->position;
        pending.input_hash = b->input_hash;
        pending.options_hash = b->options_hash;
        if (old && old->input_hash == b->input_hash && old->options_hash == b->options_hash)
            pending.estimate = old->estimate;
        todo.push_back({b, pending.estimate});
        rows.push_back(std::move(pending));
    }
    catalogue.replace_all(rows);
    return todo;
}

void order_largest_first(std::vector<PlannedBlock>& blocks) {
    std::stable_sort(blocks.begin(), blocks.end(), [](const PlannedBlock& a, const PlannedBlock& b) {
        if (a.estimate != b.estimate) return a.estimate > b.estimate;
        return a.block->position < b.block->position;
    });
}

}  // namespace tubemesh::batch
