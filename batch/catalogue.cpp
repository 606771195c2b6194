#include "batch/catalogue.hpp"

#include <sqlite3.h>

#include <algorithm>

#include "batch/test_hooks.hpp"
#include "engine/core/types.hpp"

namespace tubemesh::batch {

namespace {

namespace fs = std::filesystem;

constexpr const char* kSchema = R"(
CREATE TABLE IF NOT EXISTS blocks(
  id TEXT PRIMARY KEY,
  position INTEGER NOT NULL,
  input_hash TEXT NOT NULL,
  options_hash TEXT NOT NULL,
  status TEXT NOT NULL CHECK (status IN ('pending', 'done', 'failed')),
  error TEXT NOT NULL DEFAULT '',
  estimate REAL NOT NULL DEFAULT 0,
  nodes INTEGER NOT NULL DEFAULT 0,
  hexes INTEGER NOT NULL DEFAULT 0,
  pyramids INTEGER NOT NULL DEFAULT 0,
  tets INTEGER NOT NULL DEFAULT 0,
  tet_min REAL NOT NULL DEFAULT 0,
  tet_mean REAL NOT NULL DEFAULT 0,
  pyramid_min REAL NOT NULL DEFAULT 0,
  pyramid_mean REAL NOT NULL DEFAULT 0,
  hex_jm_min REAL NOT NULL DEFAULT 0,
  hex_jm_mean REAL NOT NULL DEFAULT 0,
  hex_cond_max REAL NOT NULL DEFAULT 0,
  phases TEXT NOT NULL DEFAULT '[]',
  seconds REAL NOT NULL DEFAULT 0,
  outputs TEXT NOT NULL DEFAULT '[]',
  report TEXT NOT NULL DEFAULT '',
  worker TEXT NOT NULL DEFAULT '',
  updated TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%SZ', 'now'))
))";

constexpr const char* kColumns =
    "id, position, input_hash, options_hash, status, error, estimate, nodes, hexes, pyramids, tets, tet_min, "
    "tet_mean, pyramid_min, pyramid_mean, hex_jm_min, hex_jm_mean, hex_cond_max, phases, seconds, outputs, report, "
    "worker";

class Statement {
public:
    Statement(sqlite3* db, const std::string& sql) : db_(db) {
        if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
            throw Error(std::string("catalogue: ") + sqlite3_errmsg(db));
    }
    ~Statement() { sqlite3_finalize(stmt_); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    void bind(int i, const std::string& v) { sqlite3_bind_text(stmt_, i, v.c_str(), -1, SQLITE_TRANSIENT); }
    void bind(int i, double v) { sqlite3_bind_double(stmt_, i, v); }
    void bind(int i, std::int64_t v) { sqlite3_bind_int64(stmt_, i, v); }
    bool step() {
        const int rc = sqlite3_step(stmt_);
        if (rc == SQLITE_ROW) return true;
        if (rc == SQLITE_DONE) return false;
        throw Error(std::string("catalogue: ") + sqlite3_errmsg(db_));
    }
    std::string text(int c) const {
        const auto* t = sqlite3_column_text(stmt_, c);
        return t ? reinterpret_cast<const char*>(t) : "";
    }
    double real(int c) const { return sqlite3_column_double(stmt_, c); }
    std::int64_t integer(int c) const { return sqlite3_column_int64(stmt_, c); }

private:
    sqlite3* db_;
    sqlite3_stmt* stmt_ = nullptr;
};

nlohmann::json outputs_json(const std::vector<OutputFile>& outputs) {
    nlohmann::json a = nlohmann::json::array();
    for (const OutputFile& o : outputs) a.push_back({{"path", o.path}, {"bytes", o.bytes}, {"sha256", o.sha256}});
    return a;
}

std::vector<OutputFile> outputs_from(const std::string& text) {
    std::vector<OutputFile> out;
    for (const nlohmann::json& o : nlohmann::json::parse(text))
        out.push_back({o.at("path").get<std::string>(), o.at("bytes").get<std::uint64_t>(),
                       o.at("sha256").get<std::string>()});
    return out;
}

BlockRecord read_row(const Statement& s) {
    BlockRecord r;
    int c = 0;
    r.id = s.text(c++);
    r.position = static_cast<int>(s.integer(c++));
    r.input_hash = s.text(c++);
    r.options_hash = s.text(c++);
    r.status = s.text(c++);
    r.error = s.text(c++);
    r.estimate = s.real(c++);
    r.nodes = s.integer(c++);
    r.hexes = s.integer(c++);
    r.pyramids = s.integer(c++);
    r.tets = s.integer(c++);
    r.tet_collapse = {s.real(c), s.real(c + 1)};
    r.pyramid_jacobian = {s.real(c + 2), s.real(c + 3)};
    r.hex_jacobian = {s.real(c + 4), s.real(c + 5)};
    c += 6;
    r.hex_condition_max = s.real(c++);
    for (const nlohmann::json& p : nlohmann::json::parse(s.text(c++)))
        r.phases.emplace_back(p.at(0).get<std::string>(), p.at(1).get<double>());
    r.seconds = s.real(c++);
    r.outputs = outputs_from(s.text(c++));
    r.report = s.text(c++);
    r.worker = s.text(c++);
    return r;
}

}  // namespace

Catalogue::Catalogue(const fs::path& path) : path_(path) {
    if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
        const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        throw Error("cannot open the catalogue '" + path.string() + "': " + why);
    }
    try {
        sqlite3_busy_timeout(db_, 30000);
        // WAL: readers (--status) never block the writer, and a killed writer leaves at most an
        // uncommitted tail that the next open discards. NORMAL sync is durable against a killed
        // process; only a power cut can lose the last commits, never corrupt the file.
        exec("PRAGMA journal_mode=WAL");
        exec("PRAGMA synchronous=NORMAL");
        exec(kSchema);
    } catch (const Error& e) {
        sqlite3_close(db_);
        throw Error("cannot use the catalogue '" + path.string() + "': " + e.what());
    }
}

Catalogue::~Catalogue() { sqlite3_close(db_); }

void Catalogue::exec(const char* sql) const {
    char* message = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        const std::string why = message ? message : sqlite3_errmsg(db_);
        sqlite3_free(message);
        throw Error("catalogue: " + why);
    }
}

std::optional<BlockRecord> Catalogue::get(const std::string& id) const {
    Statement s(db_, std::string("SELECT ") + kColumns + " FROM blocks WHERE id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return read_row(s);
}

std::vector<BlockRecord> Catalogue::all() const {
    Statement s(db_, std::string("SELECT ") + kColumns + " FROM blocks ORDER BY position, id");
    std::vector<BlockRecord> out;
    while (s.step()) out.push_back(read_row(s));
    return out;
}

void Catalogue::write(const BlockRecord& r) {
    Statement s(db_, std::string("INSERT OR REPLACE INTO blocks (") + kColumns +
                         ") VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    int c = 1;
    s.bind(c++, r.id);
    s.bind(c++, std::int64_t{r.position});
    s.bind(c++, r.input_hash);
    s.bind(c++, r.options_hash);
    s.bind(c++, r.status);
    s.bind(c++, r.error);
    s.bind(c++, r.estimate);
    s.bind(c++, r.nodes);
    s.bind(c++, r.hexes);
    s.bind(c++, r.pyramids);
    s.bind(c++, r.tets);
    for (const MeasureRecord& m : {r.tet_collapse, r.pyramid_jacobian, r.hex_jacobian}) {
        s.bind(c++, m.min);
        s.bind(c++, m.mean);
    }
    s.bind(c++, r.hex_condition_max);
    s.bind(c++, nlohmann::json(r.phases).dump());
    s.bind(c++, r.seconds);
    s.bind(c++, outputs_json(r.outputs).dump());
    s.bind(c++, r.report);
    s.bind(c++, r.worker);
    s.step();
}

void Catalogue::put(const BlockRecord& record) {
    exec("BEGIN IMMEDIATE");
    try {
        write(record);
        fault_point("commit");
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
}

void Catalogue::set_estimate(const std::string& id, double estimate) {
    Statement s(db_, "UPDATE blocks SET estimate = ? WHERE id = ?");
    s.bind(1, estimate);
    s.bind(2, id);
    s.step();
}

void Catalogue::replace_all(const std::vector<BlockRecord>& records) {
    exec("BEGIN IMMEDIATE");
    try {
        exec("CREATE TEMP TABLE IF NOT EXISTS keep(id TEXT PRIMARY KEY)");
        exec("DELETE FROM keep");
        for (const BlockRecord& r : records) {
            write(r);
            Statement s(db_, "INSERT INTO keep VALUES (?)");
            s.bind(1, r.id);
            s.step();
        }
        exec("DELETE FROM blocks WHERE id NOT IN (SELECT id FROM keep)");
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
}

void Catalogue::merge_from(const fs::path& other) {
    {
        Statement attach(db_, "ATTACH DATABASE ? AS other");
        attach.bind(1, other.string());
        attach.step();
    }
    try {
        exec("BEGIN IMMEDIATE");
        exec((std::string("INSERT OR REPLACE INTO blocks (") + kColumns + ", updated) SELECT " + kColumns +
              ", updated FROM other.blocks")
                 .c_str());
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        sqlite3_exec(db_, "DETACH DATABASE other", nullptr, nullptr, nullptr);
        throw;
    }
    exec("DETACH DATABASE other");
}

fs::path catalogue_path(const fs::path& outdir, int shard, int shards) {
    if (shards <= 0) return outdir / "catalogue.sqlite";
    return outdir / ("catalogue.shard-" + std::to_string(shard) + "-of-" + std::to_string(shards) + ".sqlite");
}

std::vector<fs::path> catalogues_in(const fs::path& outdir) {
    if (fs::exists(catalogue_path(outdir))) return {catalogue_path(outdir)};
    std::vector<fs::path> shards;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(outdir, ec)) {
        const std::string name = e.path().filename().string();
        if (name.starts_with("catalogue.shard-") && name.ends_with(".sqlite")) shards.push_back(e.path());
    }
    std::sort(shards.begin(), shards.end());
    return shards;
}

}  // namespace tubemesh::batch
