#include "tests/cli/batch_runs.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "batch/sha256.hpp"

namespace tubemesh::testing {

namespace fs = std::filesystem;

SmallDam::SmallDam() : dir(tmp / "dam") {
    const ProcessResult r = run_command(cli() + " make-dam --columns 2 --lifts 2 " + kSmallDam + " -o " + q(dir));
    if (r.exit_code != 0) ADD_FAILURE() << "make-dam failed: " << r.err;
}

ProcessResult batch(const SmallDam& dam, const std::string& out, const std::string& args, const std::string& env) {
    const std::string prefix = env.empty() ? "" : "env " + shell_quote(env) + " ";
    return run_command(prefix + cli() + " batch " + q(dam.manifest()) + " -o " + q(dam.dir / out) + " " + args);
}

namespace {

// RFC 4180 records: fields may be quoted, with "" for a quote inside.
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
    std::vector<std::vector<std::string>> records(1);
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += text[++i];
            else if (c == '"') quoted = false;
            else field += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            records.back().push_back(std::move(field));
            field.clear();
        } else if (c == '\n') {
            records.back().push_back(std::move(field));
            field.clear();
            records.emplace_back();
        } else {
            field += c;
        }
    }
    if (records.back().empty()) records.pop_back();
    return records;
}

}  // namespace

std::vector<Row> catalogue_rows(const fs::path& outdir) {
    const ProcessResult r = run_command(cli() + " batch --status " + q(outdir) + " --csv");
    if (r.exit_code == 2) ADD_FAILURE() << "batch --status failed: " << r.err;
    const auto records = parse_csv(r.out);
    std::vector<Row> rows;
    for (std::size_t i = 1; i < records.size(); ++i) {
        Row row;
        for (std::size_t c = 0; c < records[0].size() && c < records[i].size(); ++c) row[records[0][c]] = records[i][c];
        rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<Row> stable(std::vector<Row> rows) {
    for (Row& row : rows)
        for (auto it = row.begin(); it != row.end();)
            it = it->first.starts_with("seconds") || it->first == "worker" ? row.erase(it) : std::next(it);
    return rows;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string sha256_of(const fs::path& path) { return batch::sha256_file(path); }

}  // namespace tubemesh::testing
