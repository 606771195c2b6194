// The batch's acceptance run at full size (heavy): a 3 x 4 dam from `tubemesh make-dam` with
// its default, realistic blocks (lifts 15-20 x 12-18 x 1.5-3 with 25-40 mm pipes, about half a
// million elements each); every block meshed, every mesh checked and reopened by Gmsh.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/batch_runs.hpp"
#include "tests/support/outside_readers.hpp"

namespace tubemesh::testing {
namespace {

TEST(CliBatchAcceptance, ADamOfTwelveBlocksIsMeshedCheckedAndReopened) {
    TempDir tmp;
    ASSERT_EQ(run_command(cli() + " make-dam --columns 3 --lifts 4 -o " + q(tmp / "dam")).exit_code, 0);
    const ProcessResult r = run_command(cli() + " batch " + q(tmp / "dam" / "manifest.json") + " -o " + q(tmp / "out"));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const std::vector<Row> rows = catalogue_rows(tmp / "out");
    ASSERT_EQ(rows.size(), 12u);
    for (const Row& row : rows) {
        SCOPED_TRACE(row.at("id"));
        EXPECT_EQ(row.at("status"), "done");
        const auto msh = tmp / "out" / (row.at("id") + ".msh");
        EXPECT_EQ(run_command(cli() + " check " + q(msh)).exit_code, 0);
        const nlohmann::json seen = run_script("gmsh_summary.py", {msh.string()});
        EXPECT_EQ(seen["elements"].value("4", 0), std::stol(row.at("tets")));
        EXPECT_EQ(seen["elements"].value("5", 0), std::stol(row.at("hexes")));
    }
}

}  // namespace
}  // namespace tubemesh::testing
