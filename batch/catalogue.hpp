#pragma once
// The catalogue of a batch run: one SQLite database per output folder (per shard under Slurm),
// one row per block. WAL journal and one transaction per block, so a run killed at any moment
// (kill -9 included) leaves a consistent catalogue: a block is done exactly when its row says
// so, and its row says so only after its files are complete under their final names.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

struct sqlite3;

namespace tubemesh::batch {

struct OutputFile {
    std::string path;  // in the output folder
    std::uint64_t bytes = 0;
    std::string sha256;
};

// min and mean of one quality measure over a block's cells of that kind (0 when none).
struct MeasureRecord {
    double min = 0, mean = 0;
};

struct BlockRecord {
    std::string id;
    int position = 0;
    std::string input_hash, options_hash;
    std::string status = "pending";  // "pending", "done" or "failed"
    std::string error;               // one line, for a failed block
    double estimate = 0;             // lower bound on its elements (0: not known), for ordering
    std::int64_t nodes = 0, hexes = 0, pyramids = 0, tets = 0;
    MeasureRecord tet_collapse, pyramid_jacobian, hex_jacobian;
    double hex_condition_max = 0;
    std::vector<std::pair<std::string, double>> phases;  // name and seconds, in the run's order
    double seconds = 0;                                // the block's total
    std::vector<OutputFile> outputs;
    std::string report;  // the JSON report, in the output folder
    std::string worker;  // where it ran: "pid 1234", "rank 1 pid 1234"

    std::int64_t elements() const { return hexes + pyramids + tets; }
};

class Catalogue {
public:
    // Opens or creates the database; throws tubemesh::Error when it cannot.
    explicit Catalogue(const std::filesystem::path& path);
    ~Catalogue();
    Catalogue(const Catalogue&) = delete;
    Catalogue& operator=(const Catalogue&) = delete;

    std::optional<BlockRecord> get(const std::string& id) const;
    std::vector<BlockRecord> all() const;  // by position

    // Each in one transaction.
    void put(const BlockRecord& record);
    // The plan of a run: these rows replace the given ones, and rows of blocks not listed go.
    void replace_all(const std::vector<BlockRecord>& records);
    // A pending block's element estimate (batch/plan.hpp orders by it).
    void set_estimate(const std::string& id, double estimate);
    // Copies every row of another catalogue (a shard's) over this one's.
    void merge_from(const std::filesystem::path& other);

    const std::filesystem::path& path() const { return path_; }

private:
    void exec(const char* sql) const;
    void write(const BlockRecord& r);
    std::filesystem::path path_;
    sqlite3* db_ = nullptr;
};

// Where a run's catalogue lives in its output folder: catalogue.sqlite, or
// catalogue.shard-I-of-N.sqlite for shard I of N.
std::filesystem::path catalogue_path(const std::filesystem::path& outdir, int shard = -1, int shards = 0);

// Every catalogue in the folder: catalogue.sqlite if it exists, else the shards' ones.
std::vector<std::filesystem::path> catalogues_in(const std::filesystem::path& outdir);

}  // namespace tubemesh::batch
