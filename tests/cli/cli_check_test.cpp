// `tubemesh check` end to end: exit codes, the violation named, one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/io/mesh_io.hpp"
#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"
#include "tests/support/sample_meshes.hpp"

namespace {

using namespace tubemesh;
using tubemesh::testing::run_command;
using tubemesh::testing::cli;
using tubemesh::testing::shell_quote;
using tubemesh::testing::TempDir;

tubemesh::testing::ProcessResult check(const std::filesystem::path& p, const std::string& extra = "") {
    return run_command(cli() + " check " + shell_quote(p.string()) + extra);
}

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(CliCheck, ConformingPatchPasses) {
    TempDir dir;
    write_msh(tubemesh::testing::conforming_patch(), dir / "patch.msh", MshEncoding::Ascii);
    const auto r = check(dir / "patch.msh");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("valid and conforming"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Tetrahedral mesh"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Hexahedral mesh"), std::string::npos) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CliCheck, HexQuadFacingTwoTrianglesFails) {
    TempDir dir;
    write_msh(tubemesh::testing::hex_facing_two_tets(), dir / "bad.msh", MshEncoding::Binary);
    const auto r = check(dir / "bad.msh");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("NonMatchingFace"), std::string::npos) << r.out;
}

TEST(CliCheck, FlippedPyramidFails) {
    TempDir dir;
    write_msh(tubemesh::testing::flipped_pyramid_patch(), dir / "flip.msh", MshEncoding::Binary);
    const auto r = check(dir / "flip.msh");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("NonPositiveVolume"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("SameOrientation"), std::string::npos) << r.out;
}

TEST(CliCheck, JsonReportParses) {
    TempDir dir;
    write_msh(tubemesh::testing::flipped_pyramid_patch(), dir / "flip.msh", MshEncoding::Ascii);
    const auto r = check(dir / "flip.msh", " --json");
    EXPECT_EQ(r.exit_code, 1);
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_FALSE(j.at("valid_and_conforming").get<bool>());
    EXPECT_EQ(j.at("pyramids").get<int>(), 1);
    EXPECT_EQ(j.at("tets").get<int>(), 10);
    bool named = false;
    for (const auto& v : j.at("violations")) named |= v.at("kind") == "NonPositiveVolume";
    EXPECT_TRUE(named) << r.out;
}

TEST(CliCheck, MissingFileIsOneLineExitTwo) {
    TempDir dir;
    const auto r = check(dir / "nope.msh");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("nope.msh"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
}

TEST(CliCheck, GarbageFileIsOneLineExitTwo) {
    TempDir dir;
    std::ofstream(dir / "junk.msh") << "this is not a mesh\n";
    const auto r = check(dir / "junk.msh");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
}

TEST(CliCheck, UsageErrorsExitTwo) {
    EXPECT_EQ(run_command(cli() + " check").exit_code, 2);
    EXPECT_EQ(run_command(cli() + " frobnicate").exit_code, 2);
    EXPECT_EQ(run_command(cli() + " check a.msh --bogus").exit_code, 2);
}

TEST(CliCheck, HelpAndVersion) {
    const auto help = run_command(cli() + " --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("check"), std::string::npos);
    const auto check_help = run_command(cli() + " check --help");
    EXPECT_EQ(check_help.exit_code, 0);
    EXPECT_NE(check_help.out.find("--json"), std::string::npos);
    const auto version = run_command(cli() + " --version");
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_NE(version.out.find("tubemesh "), std::string::npos);
    EXPECT_NE(version.out.find("OpenCASCADE 7."), std::string::npos);
}

}  // namespace
