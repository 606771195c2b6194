// `tubemesh mesh` end to end: a STEP file from make-block through --until sweep passes
// `tubemesh check`; the default stage writes pyramids; errors leave no file behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

using tubemesh::testing::run_command;
using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::TempDir;

TEST(CliMesh, StraightPipeSweepStagePassesCheck) {
    TempDir dir;
    const auto made = run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step"));
    ASSERT_EQ(made.exit_code, 0) << made.out << made.err;
    const auto meshed = run_command(cli() + " mesh " + q(dir / "x.step") + " -o " + q(dir / "y.msh") + " --until sweep");
    ASSERT_EQ(meshed.exit_code, 0) << meshed.out << meshed.err;
    EXPECT_NE(meshed.out.find("sweep"), std::string::npos) << meshed.out;
    EXPECT_NE(meshed.out.find("Hexahedral mesh"), std::string::npos) << meshed.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "y.msh"));
    const auto checked = run_command(cli() + " check " + q(dir / "y.msh"));
    EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;
}

TEST(CliMesh, PyramidStageWritesSeveralOutputs) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step")).exit_code, 0);
    const auto r = run_command(cli() + " mesh " + q(dir / "x.step") + " -o " + q(dir / "a.msh") + " -o " +
                               q(dir / "a.vtu") + " --until pyramids --threads 2");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("pyramids"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Pyramidal mesh"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "a.msh"));
    EXPECT_TRUE(std::filesystem::exists(dir / "a.vtu"));
}

TEST(CliMesh, QuietPrintsNothing) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step")).exit_code, 0);
    const auto r = run_command(cli() + " mesh " + q(dir / "x.step") + " -o " + q(dir / "y.msh") + " --until sweep --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "y.msh"));
}

TEST(CliMesh, MissingInputIsExitTwoWithoutOutput) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh " + q(dir / "missing.step") + " -o " + q(dir / "y.msh") + " --until sweep");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(r.err.empty());
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "y.msh"));
}

TEST(CliMesh, UnknownStageIsAUsageError) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh -o " + q(dir / "y.msh") + " --until volume");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "y.msh"));
}

TEST(CliMesh, BadExtensionWritesNothing) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step")).exit_code, 0);
    const auto r = run_command(cli() + " mesh " + q(dir / "x.step") + " -o " + q(dir / "y.xyz") + " --until sweep");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "y.xyz"));
}

TEST(CliMesh, InpPastTheSweepIsRefusedUpFront) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh -o " + q(dir / "y.msh") + " -o " + q(dir / "y.inp") + " --until surface");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.err.find(".inp"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "y.msh"));
    EXPECT_FALSE(std::filesystem::exists(dir / "y.inp"));
}

TEST(CliMesh, BuiltInDamBlockWithoutInput) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh -o " + q(dir / "dam.msh") + " -o " + q(dir / "dam.inp") + " --until sweep");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("paper-ex1"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "dam.inp"));
    const auto checked = run_command(cli() + " check " + q(dir / "dam.msh"));
    EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;
}

// The README's synopsis of `mesh` names every flag the program's help lists.
TEST(CliMesh, ReadmeSynopsisHasEveryFlagOfTheHelp) {
    const auto help = run_command(cli() + " mesh --help");
    ASSERT_EQ(help.exit_code, 0) << help.err;
    std::ifstream in(std::string(TUBEMESH_SOURCE_DIR) + "/README.md");
    ASSERT_TRUE(in) << "README.md";
    // The synopsis: from "tubemesh mesh [CAD] " to the next line that does not continue it.
    std::string synopsis, line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line.rfind("tubemesh mesh [CAD] ", 0) == 0) inside = true;
        else if (inside && line.rfind("    ", 0) != 0) break;
        if (inside) synopsis += line + "\n";
    }
    ASSERT_FALSE(synopsis.empty());
    const std::regex flag("(^|[\\s,\\[|])(--[a-z][a-z-]*)");
    std::set<std::string> listed, written;
    for (std::sregex_iterator it(help.out.begin(), help.out.end(), flag), end; it != end; ++it) listed.insert((*it)[2]);
    for (std::sregex_iterator it(synopsis.begin(), synopsis.end(), flag), end; it != end; ++it) written.insert((*it)[2]);
    listed.erase("--help");
    if (synopsis.find("[-o ") != std::string::npos) listed.erase("--output");  // written as its short -o
    EXPECT_GT(listed.size(), 20u) << help.out;
    for (const std::string& f : listed) EXPECT_TRUE(written.count(f)) << f << " is not in README's synopsis:\n" << synopsis;
    for (const std::string& f : written) EXPECT_TRUE(listed.count(f)) << f << " is in README's synopsis, not in the help";
}

}  // namespace
