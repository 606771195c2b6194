// `tubemesh make-block` and `tubemesh inspect` end to end: the paper's Example 1 block written
// and inspected (text and --json), and bad arguments / unreadable files giving exactly one line
// on stderr and exit 2, with make-block leaving nothing behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

namespace fs = std::filesystem;
using tubemesh::testing::ProcessResult;
using tubemesh::testing::run_command;
using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::TempDir;

ProcessResult tubemesh_cmd(const std::string& args) { return run_command(cli() + " " + args); }

// Exactly one line: one newline, at the end, and something before it.
bool one_line(const std::string& s) {
    return s.size() > 1 && std::count(s.begin(), s.end(), '\n') == 1 && s.back() == '\n';
}

int entries(const fs::path& dir) {
    return static_cast<int>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// Writes paper-ex1 once for the inspect tests (building it takes a moment).
class CliGeomPaperEx1 : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        made_ = new ProcessResult(tubemesh_cmd("make-block --preset paper-ex1 -o " + q(*dir_ / "a.step")));
    }
    static void TearDownTestSuite() {
        delete made_;
        delete dir_;
    }
    static fs::path step() { return *dir_ / "a.step"; }
    static TempDir* dir_;
    static ProcessResult* made_;
};
TempDir* CliGeomPaperEx1::dir_ = nullptr;
ProcessResult* CliGeomPaperEx1::made_ = nullptr;

TEST_F(CliGeomPaperEx1, MakeBlockWritesTheStepFile) {
    EXPECT_EQ(made_->exit_code, 0) << made_->out << made_->err;
    EXPECT_TRUE(made_->err.empty()) << made_->err;
    EXPECT_TRUE(fs::is_regular_file(step()));
    EXPECT_NE(made_->out.find("paper-ex1, 1 pipe (diameter 0.04)"), std::string::npos) << made_->out;
    EXPECT_EQ(entries(dir_->path()), 1) << "no temporary file left beside the output";
}

TEST_F(CliGeomPaperEx1, InspectReportsOneTubeAndTheSizingPlan) {
    ASSERT_EQ(made_->exit_code, 0) << made_->err;
    const ProcessResult r = tubemesh_cmd("inspect " + q(step()));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_NE(r.out.find("\n1 tube:\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("tube 1: faces "), std::string::npos) << r.out;
    // Diameter 0.04. The wall is a B-spline sweep within ~1.2e-6 r of round, which the text
    // prints as a range when min and max differ by more than 1e-6 r ("0.02 to 0.02").
    EXPECT_TRUE(std::regex_search(r.out, std::regex(", radius 0\\.02( to 0\\.02)?, "))) << "diameter 0.04:\n" << r.out;
    EXPECT_EQ(r.out.find("tube 2:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nsizes: S = "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(", St = "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("  from S = "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("  Dc = "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("metre"), std::string::npos) << "the file's unit:\n" << r.out;
    // The block's sides, not OpenCASCADE's box around them (-1e-07) nor a vertex's -5e-17.
    EXPECT_NE(r.out.find("bounding box (0, 0, 0) to (15, 25, 4)"), std::string::npos) << r.out;
}

TEST_F(CliGeomPaperEx1, InspectJsonHasOneTubeOfDiameter004) {
    ASSERT_EQ(made_->exit_code, 0) << made_->err;
    const ProcessResult r = tubemesh_cmd("inspect --json " + q(step()));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << r.out;
    ASSERT_TRUE(j.contains("tubes"));
    ASSERT_TRUE(j["tubes"].is_array());
    ASSERT_EQ(j["tubes"].size(), 1u) << j.dump(2);
    const auto& t = j["tubes"][0];
    // Not 1e-9: paper-ex1's pipe is a B-spline path, swept within 1e-3 r (pipe_sweep.cpp); the
    // wall comes out within about 2.4e-8 of radius 0.02, so the diameter within 4.8e-8.
    constexpr double kWallTol = 1e-7;
    EXPECT_NEAR(2 * t["radius_min"].get<double>(), 0.04, kWallTol) << t.dump();
    EXPECT_NEAR(2 * t["radius_max"].get<double>(), 0.04, kWallTol) << t.dump();
    EXPECT_EQ(t["faces"].size(), 1u);
    EXPECT_TRUE(j["not_tubes"].empty()) << j["not_tubes"].dump(2);
    ASSERT_TRUE(j.contains("sizes")) << j.dump(2);
    const auto& s = j["sizes"];
    EXPECT_GT(s["S"].get<double>(), 0);
    EXPECT_GT(s["St"].get<double>(), 0);
    EXPECT_TRUE(s["changes"].is_array());
    EXPECT_TRUE(s["warnings"].is_array());
    EXPECT_EQ(j["length_unit"], "metre");
}

// The element bound `tubemesh mesh` refuses sizes on, shown before meshing: its parts add up,
// the rings count (one tube), and a size far too small is flagged as one mesh refuses.
TEST_F(CliGeomPaperEx1, InspectShowsTheElementBoundMeshChecks) {
    ASSERT_EQ(made_->exit_code, 0) << made_->err;
    const ProcessResult r = tubemesh_cmd("inspect --json " + q(step()));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const nlohmann::json b = nlohmann::json::parse(r.out).at("elements_at_least");
    const double parts = b.at("tets").get<double>() + b.at("triangles").get<double>() +
                         b.at("hexes").get<double>() + b.at("pyramids").get<double>() + b.at("quads").get<double>();
    EXPECT_NEAR(b.at("total").get<double>(), parts, 1e-9 * parts) << b.dump();
    EXPECT_GT(b.at("hexes").get<double>(), 0) << b.dump();
    EXPECT_GT(b.at("tets").get<double>(), 0) << b.dump();
    EXPECT_GT(b.at("limit").get<double>(), b.at("total").get<double>()) << b.dump();
    EXPECT_FALSE(b.at("refused").get<bool>()) << b.dump();
    EXPECT_NE(b.at("limit_source").get<std::string>().find("GiB this process may use"), std::string::npos)
        << b.dump();

    // S = 0.002 in a 15 x 25 x 4 block: ~1e12 tets. inspect still exits 0 and says so.
    const ProcessResult tiny = tubemesh_cmd("inspect --size 0.002 " + q(step()));
    EXPECT_EQ(tiny.exit_code, 0) << tiny.out << tiny.err;
    EXPECT_NE(tiny.out.find("`tubemesh mesh` refuses these sizes"), std::string::npos) << tiny.out;
    const ProcessResult tiny_json = tubemesh_cmd("inspect --json --size 0.002 " + q(step()));
    ASSERT_EQ(tiny_json.exit_code, 0) << tiny_json.err;
    EXPECT_TRUE(nlohmann::json::parse(tiny_json.out).at("elements_at_least").at("refused").get<bool>());
    TempDir out;
    const ProcessResult mesh = tubemesh_cmd("mesh --quiet --size 0.002 " + q(step()) + " -o " + q(out / "x.msh"));
    EXPECT_EQ(mesh.exit_code, 2) << mesh.out << mesh.err;
    EXPECT_FALSE(fs::exists(out / "x.msh"));
}

// Under `ulimit -v` (here 2 GiB, less than any machine this runs on) inspect shows the limit
// that binds, the one `tubemesh mesh` then checks, not the machine's memory.
TEST_F(CliGeomPaperEx1, InspectShowsTheProcessMemoryLimit) {
    ASSERT_EQ(made_->exit_code, 0) << made_->err;
    const double limit = 2.0 * 1024 * 1024 * 1024;
    const ProcessResult r =
        run_command("prlimit --as=" + std::to_string(static_cast<long long>(limit)) + " " + cli() + " inspect --json " +
                    q(step()));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const nlohmann::json b = nlohmann::json::parse(r.out).at("elements_at_least");
    EXPECT_DOUBLE_EQ(b.at("limit").get<double>(), limit / 150) << b.dump();
    EXPECT_NE(b.at("limit_source").get<std::string>().find("2 GiB this process may use (address-space limit (ulimit -v)"),
              std::string::npos)
        << b.dump();
    const ProcessResult text = run_command("prlimit --as=" + std::to_string(static_cast<long long>(limit)) + " " +
                                           cli() + " inspect " + q(step()));
    EXPECT_NE(text.out.find("limit: about 1.43e+07 elements in the 2 GiB this process may use"), std::string::npos)
        << text.out;
}

// ---- make-block errors: one line on stderr, exit 2, nothing written ----

void expect_make_block_error(const std::string& args, const std::string& what) {
    TempDir dir;
    const ProcessResult r = tubemesh_cmd("make-block " + args + " -o " + q(dir / "x.step"));
    EXPECT_EQ(r.exit_code, 2) << what << ": " << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << what << ": stderr was\n" << r.err;
    EXPECT_EQ(entries(dir.path()), 0) << what << ": make-block left a file behind";
}

TEST(CliGeomErrors, UnknownPreset) {
    TempDir dir;
    const ProcessResult r = tubemesh_cmd("make-block --preset no-such-block -o " + q(dir / "x.step"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("paper-ex1"), std::string::npos) << "lists the presets: " << r.err;
    EXPECT_EQ(entries(dir.path()), 0);
}

TEST(CliGeomErrors, PresetAndSeedTogether) { expect_make_block_error("--preset paper-ex1 --seed 3", "--preset and --seed"); }

TEST(CliGeomErrors, UnknownMakeBlockOption) { expect_make_block_error("--preset straight-pipe --frobnicate", "unknown option"); }

TEST(CliGeomErrors, SeedThatIsNotANumber) { expect_make_block_error("--seed many", "--seed many"); }

TEST(CliGeomErrors, MissingOutput) {
    TempDir dir;
    const ProcessResult r = run_command("cd " + q(dir.path()) + " && " + cli() + " make-block --preset straight-pipe");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("-o"), std::string::npos) << r.err;
    EXPECT_EQ(entries(dir.path()), 0);
}

TEST(CliGeomErrors, OutputInAMissingDirectory) {
    TempDir dir;
    const ProcessResult r =
        tubemesh_cmd("make-block --preset straight-pipe -o " + q(dir / "no_such_dir" / "x.step"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_EQ(entries(dir.path()), 0);
}

// A full disk (here a file-size limit below the STEP file's size) is named by the system's
// reason, not guessed at, and leaves no file.
TEST(CliGeomErrors, AFullDiskGivesTheRealReasonAndNoFile) {
    TempDir dir;
    const ProcessResult r = run_command("prlimit --fsize=4096 " + cli() + " make-block --preset straight-pipe -o " +
                                        q(dir / "x.step"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("cannot write '" + (dir / "x.step").string() + "': File too large"), std::string::npos)
        << r.err;
    EXPECT_EQ(entries(dir.path()), 0);
}

TEST(CliGeomErrors, MissingSpecFile) {
    TempDir dir;
    const ProcessResult r = tubemesh_cmd("make-block --spec " + q(dir / "none.json") + " -o " + q(dir / "x.step"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_EQ(entries(dir.path()), 0);
}

// ---- inspect errors ----

void expect_inspect_error(const std::string& args, const std::string& what) {
    const ProcessResult r = tubemesh_cmd("inspect " + args);
    EXPECT_EQ(r.exit_code, 2) << what << ": " << r.out << r.err;
    EXPECT_TRUE(one_line(r.err)) << what << ": stderr was\n" << r.err;
}

TEST(CliGeomErrors, InspectMissingFile) {
    TempDir dir;
    expect_inspect_error(q(dir / "missing.step"), "missing file");
    expect_inspect_error(q(dir / "missing.step") + " --json", "missing file, --json");
}

TEST(CliGeomErrors, InspectGarbageFile) {
    TempDir dir;
    std::ofstream(dir / "garbage.step") << "ISO-10303-21;\nthis is not really STEP\x01\x02\n";
    std::ofstream(dir / "garbage.txt") << "hello\n";
    expect_inspect_error(q(dir / "garbage.step"), "garbage .step");
    expect_inspect_error(q(dir / "garbage.txt"), "garbage .txt");
    expect_inspect_error(q(dir / "garbage.step") + " --json", "garbage .step, --json");
}

TEST(CliGeomErrors, InspectDirectory) {
    TempDir dir;
    fs::create_directories(dir / "folder.step");
    expect_inspect_error(q(dir.path()), "a directory");
    expect_inspect_error(q(dir / "folder.step"), "a directory named .step");
}

TEST(CliGeomErrors, InspectBadArguments) {
    TempDir dir;
    expect_inspect_error("", "no file");
    expect_inspect_error("--frobnicate " + q(dir / "a.step"), "unknown option");
    expect_inspect_error(q(dir / "a.step") + " --size -1", "negative size");
}

}  // namespace
