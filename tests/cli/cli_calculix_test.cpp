// The .inp as a solver reads it: CalculiX (Debian's ccx) runs decks on meshes that
// `tubemesh mesh` wrote, and every figure it computes is checked against the exact answer
// (tests/scripts/calculix_run.py writes the decks and reads the results):
//  * a patch test - T = x + 2y + 3z fixed on every boundary node, reproduced at every node
//    (a misread coordinate, a mis-numbered element or a hanging node breaks it) - on the
//    built-in dam block, paper-ex2, a random block, and a T-junction and two crossing pipes
//    (walls that meet: tets there, a ring on the pipe away from them);
//  * the dam block's pipe at 10 and top at 25: every temperature in [10, 25], once with fixed
//    temperatures on the node sets, once with a *FILM on the pipe's element-face sets;
//  * the dam block under gravity, bottom fixed: the top moves as a column does;
//  * the README's CalculiX deck, as written;
// and no number field of any random block's .inp is longer than CalculiX reads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/mesh_io_samples.hpp"
#include "tests/support/cli_test_names.hpp"
#include "tests/support/outside_readers.hpp"
#include "tests/support/readme_blocks.hpp"

namespace tubemesh {
namespace {

using testing::run_script;

// A block whose pipe walls meet, meshed with tets there instead of a ring (as in
// tests/geom_ring_fallback_test.cpp): a 4 x 4 x 4 box with a pipe along y = 3.2 and either a
// narrower blind branch ending in it (the T) or a pipe crossing it (the cross), and far from them
// a pipe along x that keeps its ring.
std::string meeting_pipes_spec(const std::string& case_name) {
    const std::string branch = case_name == "T-junction"
                                   ? R"({"path": "line", "diameter": 0.14, "points": [[2, 0, 3], [2, 3.2, 3]],)"
                                     R"( "blind": true})"
                                   : R"({"path": "line", "diameter": 0.2, "points": [[2, 0, 3], [2, 4, 3]]})";
    return R"({"box": [4, 4, 4], "check_clearance": false, "pipes": [)"
           R"({"path": "line", "diameter": 0.2, "points": [[0, 0.8, 0.8], [4, 0.8, 0.8]]}, )"
           R"({"path": "line", "diameter": 0.2, "points": [[0, 3.2, 3], [4, 3.2, 3]]}, )" +
           branch + "]}";
}

// Writes `case_name`'s mesh as .inp into `dir`: "dam" is the built-in block, "paper-ex2" the
// preset through STEP at the paper's S 1.1, "seed N" a random block, "T-junction" and "crossing
// pipes" the blocks of meeting_pipes_spec.
std::filesystem::path mesh_inp(const TempDir& dir, const std::string& case_name) {
    const auto inp = dir / "mesh.inp";
    std::string mesh = cli() + " mesh --quiet --threads 2 -o " + q(inp);
    if (case_name != "dam") {
        const auto step = dir / "block.step";
        std::string source = case_name.rfind("seed ", 0) == 0 ? "--seed " + case_name.substr(5)
                                                              : "--preset " + case_name;
        if (case_name == "T-junction" || case_name == "crossing pipes") {
            testing::write_text(dir / "block.json", meeting_pipes_spec(case_name));
            source = "--spec " + q(dir / "block.json");
        }
        const auto made = run_command(cli() + " make-block " + source + " -o " + q(step));
        EXPECT_EQ(made.exit_code, 0) << made.err;
        mesh.append(" ").append(q(step)).append(case_name == "paper-ex2" ? " --size 1.1" : "");
    }
    const auto meshed = run_command(mesh);
    EXPECT_EQ(meshed.exit_code, 0) << meshed.out << meshed.err;
    return inp;
}

json calculix(const std::string& mode, std::vector<std::string> args) {
    args.insert(args.begin(), mode);
    return run_script("calculix_run.py", args);
}

class CalculixPatch : public ::testing::TestWithParam<const char*> {};

TEST_P(CalculixPatch, ReproducesALinearTemperatureAtEveryNode) {
    TempDir dir;
    const auto inp = mesh_inp(dir, GetParam());
    const json r = calculix("patch", {inp.string(), dir.path().string()});
    std::cout << GetParam() << " patch test: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("relative_error")) << r.dump();
    EXPECT_GT(r["boundary_nodes"].get<int>(), 0);
    EXPECT_LT(r["boundary_nodes"].get<int>(), r["nodes"].get<int>());  // interior nodes are computed
    EXPECT_LT(r["relative_error"].get<double>(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Meshes, CalculixPatch,
                         ::testing::Values("dam", "paper-ex2", "seed 7", "T-junction", "crossing pipes"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

class DamBlockInCalculix : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        inp_ = mesh_inp(*dir_, "dam");
    }
    static void TearDownTestSuite() {
        delete dir_;
        dir_ = nullptr;
    }
    static inline TempDir* dir_ = nullptr;
    static inline std::filesystem::path inp_;
};

TEST_F(DamBlockInCalculix, PipeAtTenTopAtTwentyFive) {
    for (const char* variant : {"boundary", "film"}) {
        TempDir work;
        const json r = calculix("thermal", {inp_.string(), work.path().string(), "pipe_1", "top", variant});
        std::cout << "dam block, pipe 10, top 25 (" << variant << "): " << r.dump() << "\n";
        ASSERT_TRUE(r.contains("t_min")) << r.dump();
        EXPECT_GE(r["t_min"].get<double>(), 10.0 - 1e-5) << variant;
        EXPECT_LE(r["t_max"].get<double>(), 25.0 + 1e-5) << variant;
        EXPECT_NEAR(r["pipe_t_min"].get<double>(), 10.0, 1e-4) << variant;
        EXPECT_NEAR(r["pipe_t_max"].get<double>(), 10.0, 1e-4) << variant;
        if (std::string(variant) == "film") {
            EXPECT_GT(r["film_lines"].get<int>(), 0);
        }
    }
}

TEST_F(DamBlockInCalculix, GravityMovesTheTopAsAColumn) {
    TempDir work;
    const json r = calculix("gravity", {inp_.string(), work.path().string(), "bottom"});
    std::cout << "dam block under gravity: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("ratio")) << r.dump();
    EXPECT_NEAR(r["ratio"].get<double>(), 1.0, 0.05);
}

// The deck between the README's "calculix-deck" markers runs as written on the block that
// tools/run.sh writes (dam_block.inp).
TEST_F(DamBlockInCalculix, TheReadmeDeckRunsAsWritten) {
    const std::string deck = testing::readme_block("calculix-deck");
    ASSERT_FALSE(deck.empty());
    TempDir work;
    testing::write_text(work / "dam_heat.inp", deck);
    std::filesystem::copy_file(inp_, work / "dam_block.inp");
    TempDir run;
    const json r = calculix("deck", {(work / "dam_heat.inp").string(), (work / "dam_block.inp").string(),
                                     run.path().string()});
    std::cout << "README deck: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("t_min")) << r.dump();
    EXPECT_GE(r["t_min"].get<double>(), 10.0 - 1e-5);
    EXPECT_LE(r["t_max"].get<double>(), 25.0 + 1e-5);
    EXPECT_LT(r["t_min"].get<double>(), 20.0);  // the cooling water is felt
}

// CalculiX reads at most 20 characters of a number: every field of every data line fits.
class InpFieldWidth : public ::testing::TestWithParam<int> {};

TEST_P(InpFieldWidth, NoFieldOverTwentyCharacters) {
    TempDir dir;
    const auto inp = mesh_inp(dir, "seed " + std::to_string(GetParam()));
    std::ifstream in(inp);
    std::string line;
    std::size_t lines = 0, longest = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '*') continue;
        ++lines;
        std::stringstream fields(line);
        for (std::string field; std::getline(fields, field, ',');) {
            const auto first = field.find_first_not_of(' '), last = field.find_last_not_of(' ');
            if (first != std::string::npos) longest = std::max(longest, last - first + 1);
        }
    }
    EXPECT_GT(lines, 1000u);
    EXPECT_LE(longest, 20u);
}

INSTANTIATE_TEST_SUITE_P(Seeds, InpFieldWidth, ::testing::Range(1, 51));

}  // namespace
}  // namespace tubemesh
