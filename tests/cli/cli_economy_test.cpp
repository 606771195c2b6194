// The economy preset on the paper's three examples at the paper's S, through `tubemesh mesh
// --economy`: the cells of Table 1 it meets (bench/results/table1-*.md has the whole table and
// the cells it misses), the paper's column beside ours in the text and JSON reports, and the
// options given beside the preset winning over it.
//
// Not met (the tet step's part): the tet mean collapse on all three (0.82 / 0.80 / 0.81 in the
// paper), the tet minimum and the pyramid minimum on paper-ex1 and paper-ex2's element total.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_names.hpp"

namespace tubemesh {
namespace {

struct MeshRun {
    std::string out;
    json report;
};

// `tubemesh mesh <preset's STEP> --size S <options>`, once per command line.
const MeshRun& mesh(const std::string& preset, const std::string& size, const std::string& options) {
    static TempDir dir;
    static std::map<std::string, MeshRun> runs;
    const std::string key = preset + " " + size + " " + options;
    auto [it, fresh] = runs.try_emplace(key);
    if (!fresh) return it->second;
    const std::filesystem::path step = testing::built_preset(dir.path(), preset);
    const std::filesystem::path report = dir.path() / (std::to_string(runs.size()) + ".json");
    const auto meshed = run_command(cli() + " mesh " + q(step) + " --size " + size + " " + options + " -o " +
                                    q(dir.path() / "out.msh") + " --report " + q(report));
    EXPECT_EQ(meshed.exit_code, 0) << meshed.out << meshed.err;
    it->second.out = meshed.out;
    if (meshed.exit_code == 0) it->second.report = json::parse(std::ifstream(report));
    return it->second;
}

double total(const json& r) {
    return r["hexes"].get<double>() + r["pyramids"].get<double>() + r["tets"].get<double>();
}
double quality(const json& r, const char* measure, const char* stat) { return r["quality"][measure][stat].get<double>(); }

// Every example: the rings within the analysis limits, as the paper's (hex J_m >= 0.5, Cond <= 4).
void expect_hexes_acceptable(const json& r) {
    EXPECT_GE(quality(r, "hex_scaled_jacobian", "min"), 0.5);
    EXPECT_LE(quality(r, "hex_condition", "max"), 4.0);
}

TEST(CliEconomy, PaperEx1MeetsTheElementTotalAndTheTetMean) {
    const json& r = mesh("paper-ex1", "0.6", "--economy").report;
    ASSERT_FALSE(r.is_null());
    EXPECT_LE(total(r), 58594);
    EXPECT_GE(quality(r, "tet_collapse", "mean"), 0.819);
    expect_hexes_acceptable(r);
    EXPECT_LT(total(r), 0.55 * total(mesh("paper-ex1", "0.6", "").report));  // the default needs ~2x
}

TEST(CliEconomy, PaperEx2MeetsTheTetAndPyramidMinima) {
    const json& r = mesh("paper-ex2", "1.1", "--economy").report;
    ASSERT_FALSE(r.is_null());
    EXPECT_GE(quality(r, "tet_collapse", "min"), 0.304);
    EXPECT_GE(quality(r, "pyramid_scaled_jacobian", "min"), 0.451);
    expect_hexes_acceptable(r);
    EXPECT_LE(total(r), 1.2 * 9412);  // not the paper's total yet: within 20 %
}

TEST(CliEconomy, PaperEx3MeetsTheElementTotalAndTheMinima) {
    const json& r = mesh("paper-ex3", "40", "--economy").report;
    ASSERT_FALSE(r.is_null());
    EXPECT_LE(total(r), 6997);
    EXPECT_GE(quality(r, "tet_collapse", "min"), 0.258);
    EXPECT_GE(quality(r, "pyramid_scaled_jacobian", "min"), 0.369);
    expect_hexes_acceptable(r);
}

TEST(CliEconomy, ReportShowsThePapersColumnForItsExamplesOnly) {
    const MeshRun& ex3 = mesh("paper-ex3", "40", "--economy");
    EXPECT_NE(ex3.out.find("Paper's Table 1, Example 3 (paper-ex3), beside this mesh"), std::string::npos) << ex3.out;
    const json& paper = ex3.report["paper_table1"];
    ASSERT_TRUE(paper.is_object());
    EXPECT_EQ(paper["example"], 3);
    EXPECT_EQ(ex3.report["name"], "paper-ex3");
    ASSERT_EQ(paper["rows"][0]["key"], "elements");
    EXPECT_EQ(paper["rows"][0]["paper"].get<double>(), 6997);
    EXPECT_EQ(paper["rows"][0]["this_mesh"].get<double>(), total(ex3.report));

    const MeshRun& other = mesh("straight-pipe", "0.5", "--economy");
    ASSERT_FALSE(other.report.is_null());
    EXPECT_EQ(other.report["name"], "straight-pipe");
    EXPECT_FALSE(other.report.contains("paper_table1"));
    EXPECT_EQ(other.out.find("Paper's Table 1"), std::string::npos);
}

TEST(CliEconomy, GivenOptionsWinOverThePreset) {
    // St: 0.42 S from the preset, held at 12.5 tube radii (0.25 here), the given value beside it;
    // n: 4 from the preset, 8 given.
    const json& preset = mesh("paper-ex1", "0.6", "--economy").report;
    EXPECT_NEAR(preset["sizes"]["St"].get<double>(), 12.5 * 0.02, 1e-3 * 0.25);  // the wall's radius within 1e-3 r
    const json& given = mesh("paper-ex1", "0.6", "--economy --sweep-size 0.2 --circ 8").report;
    ASSERT_FALSE(given.is_null());
    EXPECT_EQ(given["sizes"]["St"].get<double>(), 0.2);
    EXPECT_EQ(given["pyramids"].get<int>() % 8, 0);
    EXPECT_GT(given["pyramids"].get<int>(), preset["pyramids"].get<int>());
}

}  // namespace
}  // namespace tubemesh
