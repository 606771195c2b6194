#include "batch/plan.hpp"

#include <algorithm>

#include "batch/sha256.hpp"
#include "engine/core/types.hpp"

namespace tubemesh::batch {

namespace fs = std::filesystem;

std::vector<const BlockEntry*> shard_blocks(const Manifest& manifest, int shard, int shards) {
    std::vector<const BlockEntry*> out;
    for (const BlockEntry& b : manifest.blocks)
        if (shards <= 0 || b.position % shards == shard) out.push_back(&b);
    return out;
}

std::string changed_output(const BlockRecord& row, const fs::path& outdir) {
    std::error_code ec;
    for (const OutputFile& f : row.outputs) {
        const fs::path path = outdir / f.path;
        if (!fs::exists(path, ec)) return f.path + " is missing";
        // The size first: a cheap answer for most changes, before the file is read through.
        if (fs::file_size(path, ec) != f.bytes || ec) return f.path + " changed since it was written";
        try {
            if (sha256_file(path) != f.sha256) return f.path + " changed since it was written";
        } catch (const Error& e) {
            return e.what();
        }
    }
    if (!fs::exists(outdir / row.report, ec)) return row.report + " is missing";
    return {};
}

bool done_and_intact(const BlockRecord& row, const BlockEntry& block, const fs::path& outdir) {
    if (row.status != "done" || row.input_hash != block.input_hash || row.options_hash != block.options_hash)
        return false;
    return changed_output(row, outdir).empty();
}

void recheck_done_rows(std::vector<BlockRecord>& rows, const fs::path& outdir) {
    for (BlockRecord& r : rows) {
        if (r.status != "done") continue;
        std::string change = changed_output(r, outdir);
        if (change.empty()) continue;
        r.status = "pending";
        r.error = std::move(change);
    }
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
