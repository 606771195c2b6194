#pragma once
// Helpers of the batch tests: a small dam from `tubemesh make-dam`, batch runs on it, and the
// catalogue as rows of `tubemesh batch --status --csv`.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tests/support/cli_command.hpp"

namespace tubemesh::testing {

// make-dam ranges for blocks of 3 x 3 x 1 with a 0.08-0.1 pipe: about 14,000 elements, half a
// second each.
inline const std::string kSmallDam =
    "--width 3:3.5 --depth 3:3.5 --lift-height 1:1.2 --diameter 0.08:0.1 --spacing 0.9:1.1";

// A 2 x 2 dam (two blocks with a pipe, the foundation and the crest without) as STEP files
// and manifest.json in a fresh folder.
struct SmallDam {
    SmallDam();
    TempDir tmp;
    std::filesystem::path dir;
    std::filesystem::path manifest() const { return dir / "manifest.json"; }
};

// `tubemesh batch MANIFEST -o DIR/OUT ARGS`, with `env` ("NAME=value") set for it.
ProcessResult batch(const SmallDam& dam, const std::string& out, const std::string& args,
                    const std::string& env = "");

using Row = std::map<std::string, std::string>;
// The catalogue of an output folder, one row per block in manifest order (column -> value).
std::vector<Row> catalogue_rows(const std::filesystem::path& outdir);
// The rows without what differs between identical runs: times and the worker's pid.
std::vector<Row> stable(std::vector<Row> rows);

std::string read_text(const std::filesystem::path& path);
std::string sha256_of(const std::filesystem::path& path);

}  // namespace tubemesh::testing
