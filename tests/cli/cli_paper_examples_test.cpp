// Acceptance of the paper's three examples (our builders' versions), end to end
// through `tubemesh mesh` with --size 0.6, 1.1 and 40 and every other option at its default:
// the run succeeds (so our check passed before anything was written), the Table-1 report is
// printed, Gmsh reopens the .msh with the same counts and groups, the hex and pyramid bars
// hold, and the element total is within a factor 2 of the paper's.
//
// One source, two executables: test_cli_paper_examples (CI) runs everything that holds today,
// the tet collapse minimum of 0.30 included; test_cli_paper_examples_gaps (TUBEMESH_PAPER_GAPS,
// labels heavy and known_gap) what does not yet: the mean tet collapse of 0.80 (the tet step's bar) on all
// three, and the element count of paper-ex2 (26 k against the paper's 9,412: the paper's rings
// are far coarser than the rings' defaults of 8 nodes around and an axial aspect of 1.5 allow;
// `--economy` comes within 14 %, tests/cli/cli_economy_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/io/mesh_io.hpp"
#include "tests/support/cli_command.hpp"
#include "tests/support/outside_readers.hpp"
#include "tests/support/process.hpp"

namespace tubemesh {
namespace {

using nlohmann::json;
using testing::run_command;
using testing::cli;
using testing::q;
using testing::TempDir;

struct Example {
    const char* preset;
    const char* size;
    double paper_total;  // Table 1: hexes + pyramids + tets
};

const Example kExamples[] = {{"paper-ex1", "0.6", 1432 + 716 + 56446},
                             {"paper-ex2", "1.1", 320 + 160 + 8932},
                             {"paper-ex3", "40", 56 + 56 + 6885}};

// One run per example, shared by the tests below.
struct ExampleRun {
    std::string out;   // what `tubemesh mesh` printed
    json report;       // --report
    HybridMesh mesh;   // the .msh as tubemesh reads it
    std::filesystem::path msh;
};

const ExampleRun& run(const Example& e) {
    static TempDir dir;
    static std::map<std::string, ExampleRun> runs;
    auto [it, fresh] = runs.try_emplace(e.preset);
    ExampleRun& r = it->second;
    if (!fresh) return r;
    const std::filesystem::path step = dir.path() / (std::string(e.preset) + ".step");
    r.msh = dir.path() / (std::string(e.preset) + ".msh");
    const std::filesystem::path report = dir.path() / (std::string(e.preset) + ".json");
    const auto made = run_command(cli() + " make-block --preset " + e.preset + " -o " + q(step));
    EXPECT_EQ(made.exit_code, 0) << made.err;
    const auto meshed =
        run_command(cli() + " mesh " + q(step) + " --size " + e.size + " -o " + q(r.msh) + " --report " + q(report));
    EXPECT_EQ(meshed.exit_code, 0) << meshed.out << meshed.err;
    r.out = meshed.out;
    if (meshed.exit_code != 0) return r;
    std::ifstream in(report);
    r.report = json::parse(in);
    r.mesh = read_msh(r.msh);
    return r;
}

double total(const json& report) {
    return report["hexes"].get<double>() + report["pyramids"].get<double>() + report["tets"].get<double>();
}

class PaperExample : public ::testing::TestWithParam<Example> {};

#ifndef TUBEMESH_PAPER_GAPS

// One test per example (each ctest test is its own process and meshes its example again).
TEST_P(PaperExample, MeshesEndToEndIsReportedReopenedAndMeetsTheBars) {
    const ExampleRun& r = run(GetParam());
    ASSERT_FALSE(r.report.is_null());
    EXPECT_EQ(r.report["stage"], "tets");
    // The Table-1 report on stdout.
    for (const char* line : {"Tetrahedral mesh", "Pyramidal mesh", "Hexahedral mesh", "Min. J_m", "Avg. metric",
                             "Nodes", "Total time", "Elements / second"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line;
    EXPECT_GT(r.mesh.cell_count(CellKind::Hex), 0u);
    EXPECT_GT(r.mesh.cell_count(CellKind::Pyramid), 0u);
    EXPECT_GT(r.mesh.cell_count(CellKind::Tet), 0u);
    EXPECT_EQ(r.report["hexes"], r.mesh.cell_count(CellKind::Hex));
    EXPECT_EQ(r.report["tets"], r.mesh.cell_count(CellKind::Tet));

    // Gmsh reopens the .msh with the same counts and groups.
    const json seen = testing::run_script("gmsh_summary.py", {r.msh.string()});
    EXPECT_EQ(seen["nodes"], r.mesh.point_count());
    EXPECT_EQ(seen["elements"].get<testing::Counts>(), testing::gmsh_counts(r.mesh));
    EXPECT_EQ(seen["physical"], testing::physical_groups(r.mesh));

    // The ring, pyramid and tet bars (the tet mean collapse of 0.80, not met yet: the _gaps build).
    const json& quality = r.report["quality"];
    ASSERT_TRUE(quality.is_object());
    EXPECT_GE(quality["hex_scaled_jacobian"]["min"].get<double>(), 0.5);
    EXPECT_LE(quality["hex_condition"]["max"].get<double>(), 4.0);
    EXPECT_GE(quality["pyramid_scaled_jacobian"]["min"].get<double>(), 0.45);
    EXPECT_GE(quality["pyramid_scaled_jacobian"]["mean"].get<double>(), 0.80);
    EXPECT_GE(quality["tet_collapse"]["min"].get<double>(), 0.30);  // so none below 0.20 either

    // Within a factor 2 of the paper's total, except where that is a known gap (paper-ex2).
    if (std::string(GetParam().preset) != "paper-ex2") {
        EXPECT_LE(total(r.report), 2 * GetParam().paper_total);
        EXPECT_GE(total(r.report), 0.5 * GetParam().paper_total);
    }
}

#else

class PaperExampleCount : public PaperExample {};

TEST_P(PaperExampleCount, ElementTotalWithinAFactorTwoOfThePaper) {
    const ExampleRun& r = run(GetParam());
    ASSERT_FALSE(r.report.is_null());
    EXPECT_LE(total(r.report), 2 * GetParam().paper_total);
    EXPECT_GE(total(r.report), 0.5 * GetParam().paper_total);
}

TEST_P(PaperExample, TetMeanCollapseReachesThePapers) {
    const ExampleRun& r = run(GetParam());
    ASSERT_FALSE(r.report.is_null());
    EXPECT_GE(r.report["quality"]["tet_collapse"]["mean"].get<double>(), 0.80);
}

#endif

std::string name(const ::testing::TestParamInfo<Example>& info) {
    std::string n = info.param.preset;
    for (char& c : n)
        if (c == '-') c = '_';
    return n;
}

#ifndef TUBEMESH_PAPER_GAPS
INSTANTIATE_TEST_SUITE_P(Paper, PaperExample, ::testing::ValuesIn(kExamples), name);
#else
INSTANTIATE_TEST_SUITE_P(Paper, PaperExample, ::testing::ValuesIn(kExamples), name);
INSTANTIATE_TEST_SUITE_P(Paper, PaperExampleCount, ::testing::Values(kExamples[1]), name);
#endif

}  // namespace
}  // namespace tubemesh
