// `tubemesh mesh` outputs: the --report JSON matches the written mesh, --circ / --layers change
// the hex counts as the ring's numbering says (hexes = stations-1 layers x L x n), the .msh
// holds the pipe wall, face and volume groups, progress lines appear when stdout is not a
// terminal, and --quiet prints nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "engine/io/mesh_io.hpp"
#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

using tubemesh::testing::run_command;
using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::TempDir;

nlohmann::json read_json(const std::filesystem::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

struct Meshed {
    nlohmann::json report;
    tubemesh::HybridMesh mesh;
};

Meshed mesh_pipe(const TempDir& dir, const std::string& extra) {
    const auto step = dir / "pipe.step";
    if (!std::filesystem::exists(step)) {
        const auto made = run_command(cli() + " make-block --preset straight-pipe -o " + q(step));
        EXPECT_EQ(made.exit_code, 0) << made.err;
    }
    const auto r = run_command(cli() + " mesh " + q(step) + " -o " + q(dir / "m.msh") + " --report " +
                               q(dir / "r.json") + " --quiet " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return {read_json(dir / "r.json"), tubemesh::read_msh(dir / "m.msh")};
}

TEST(CliMeshReport, JsonCountsMatchTheWrittenMesh) {
    TempDir dir;
    const Meshed m = mesh_pipe(dir, "");
    const auto& j = m.report;
    EXPECT_EQ(j["nodes"].get<unsigned>(), m.mesh.point_count());
    EXPECT_EQ(j["hexes"].get<unsigned>(), m.mesh.cell_count(tubemesh::CellKind::Hex));
    EXPECT_EQ(j["pyramids"].get<unsigned>(), m.mesh.cell_count(tubemesh::CellKind::Pyramid));
    EXPECT_EQ(j["tets"].get<unsigned>(), m.mesh.cell_count(tubemesh::CellKind::Tet));
    EXPECT_EQ(j["boundary_triangles"].get<unsigned>(), m.mesh.face_count(tubemesh::FaceKind::Tri));
    EXPECT_EQ(j["quality"]["hex_scaled_jacobian"]["count"].get<unsigned>(), m.mesh.cell_count(tubemesh::CellKind::Hex));
    EXPECT_GT(j["hexes"].get<unsigned>(), 0u);
    EXPECT_EQ(j["pyramids"].get<unsigned>() * 2, j["hexes"].get<unsigned>());  // one per outer quad, L = 2
    double sum = 0;
    for (const auto& p : j["phases"]) sum += p["seconds"].get<double>();
    EXPECT_NEAR(sum, j["total_seconds"].get<double>(), 1e-9);
    std::vector<std::string> names;
    for (const auto& p : j["phases"]) names.push_back(p["name"]);
    for (const char* want : {"import", "tubes", "sizes", "discretize", "sweep", "surface", "pyramids", "check"})
        EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
}

// The sweep also resamples the stations (axial aspect, condition cap), so the count is not
// simply proportional to n or L; the ring's numbering is: hexes = L x outer quads, and the
// outer quads are n per axial layer.
TEST(CliMeshReport, CircAndLayersSetTheRingNumbering) {
    TempDir dir;
    unsigned previous = 0;
    for (const auto& [n, layers] : {std::pair{8u, 2u}, {16u, 2u}, {16u, 3u}}) {
        const nlohmann::json j = mesh_pipe(dir, "--until sweep --circ " + std::to_string(n) + " --layers " +
                                                    std::to_string(layers)).report;
        nlohmann::json sweep, disc;
        for (const auto& p : j["phases"]) {
            if (p["name"] == "sweep") sweep = p["counts"];
            if (p["name"] == "discretize") disc = p["counts"];
        }
        const unsigned hexes = j["hexes"].get<unsigned>();
        const unsigned outer = sweep["outer quads"].get<unsigned>();
        EXPECT_EQ(disc["nodes around (fewest)"].get<unsigned>(), n);
        EXPECT_EQ(hexes, layers * outer) << n << " " << layers;
        EXPECT_EQ(outer % n, 0u) << n << " " << layers;
        EXPECT_GT(hexes, previous);
        previous = hexes;
    }
}

// --tet-relax sets the tet step's ODT relaxation rounds (reported): none moves no point, two
// move more than one, the default is one; the default's relaxed points give a better mean
// collapse than none (the far field's lattice points stay in place, so not every point moves).
TEST(CliMeshReport, TetRelaxSetsTheRelaxationRounds) {
    TempDir dir;
    const auto tets_counts = [](const nlohmann::json& j) {
        for (const auto& p : j["phases"]) {
            if (p["name"] == "tets") return p["counts"];
        }
        return nlohmann::json();
    };
    const nlohmann::json off = mesh_pipe(dir, "--tet-relax 0").report;
    const nlohmann::json two = mesh_pipe(dir, "--tet-relax 2").report;
    const nlohmann::json on = mesh_pipe(dir, "").report;
    EXPECT_EQ(tets_counts(off)["relaxation rounds"].get<double>(), 0.0);
    EXPECT_EQ(tets_counts(two)["relaxation rounds"].get<double>(), 2.0);
    EXPECT_EQ(tets_counts(on)["relaxation rounds"].get<double>(), 1.0);
    EXPECT_EQ(tets_counts(off)["relaxation moves"].get<double>(), 0.0);
    EXPECT_GT(tets_counts(two)["relaxation moves"].get<double>(), tets_counts(on)["relaxation moves"].get<double>());
    EXPECT_GT(tets_counts(on)["relaxation moves"].get<double>(), 0.0);
    EXPECT_GT(on["quality"]["tet_collapse"]["mean"].get<double>(), off["quality"]["tet_collapse"]["mean"].get<double>());
    const auto bad = run_command(cli() + " mesh --tet-relax 17 -o " + q(dir / "x.msh"));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "x.msh"));
}

TEST(CliMeshReport, MshHoldsPipeFaceAndVolumeGroups) {
    TempDir dir;
    const Meshed m = mesh_pipe(dir, "");
    const auto& s = m.mesh.surface_group_names;
    EXPECT_NE(std::find(s.begin(), s.end(), "pipe_1"), s.end());
    // The box's six faces: every non-wall B-rep face is a group.
    EXPECT_EQ(std::count_if(s.begin(), s.end(), [](const std::string& g) { return g.rfind("face_", 0) == 0; }), 6);
    const auto& r = m.mesh.region_names;
    EXPECT_NE(std::find(r.begin(), r.end(), "hex_ring"), r.end());
    EXPECT_NE(std::find(r.begin(), r.end(), "pyramids"), r.end());
}

TEST(CliMeshReport, PlainProgressLinesWhenNotATerminal) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step")).exit_code, 0);
    const auto r = run_command(cli() + " mesh " + q(dir / "x.step") + " -o " + q(dir / "y.msh"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // One line per phase, each phase once (the tet step's last part used to repeat it).
    for (const char* phase : {"import", "sweep", "surface", "pyramids", "tets", "check"}) {
        const std::string line = std::string("progress: ") + phase + " ";
        const std::size_t at = r.out.find(line);
        EXPECT_NE(at, std::string::npos) << phase << "\n" << r.out;
        if (at != std::string::npos) {
            EXPECT_EQ(r.out.find(line, at + 1), std::string::npos) << phase << "\n" << r.out;
        }
    }
    EXPECT_EQ(r.out.find('\r'), std::string::npos);  // no terminal control in a log
    EXPECT_NE(r.out.find("Total time"), std::string::npos);
    EXPECT_NE(r.out.find("Elements / second"), std::string::npos);
}

TEST(CliMeshReport, QuietPrintsNothingAtAll) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step")).exit_code, 0);
    const auto r = run_command(cli() + " mesh " + q(dir / "x.step") + " -o " + q(dir / "y.msh") + " --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "y.msh"));
}

TEST(CliMeshReport, NoInputNoOutputWritesTheDamBlockFiles) {
    TempDir dir;
    const auto r = run_command("cd " + q(dir.path()) + " && " + cli() + " mesh --until sweep --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "dam_block.msh"));
    EXPECT_TRUE(std::filesystem::exists(dir / "dam_block.vtu"));
}

// A report alone is a whole run: the mesh is made and checked, only the report files are written.
TEST(CliMeshReport, ReportsAloneWriteOnlyTheReports) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "x.step")).exit_code, 0);
    const auto html = run_command(cli() + " mesh " + q(dir / "x.step") + " --quiet --html " + q(dir / "r.html"));
    ASSERT_EQ(html.exit_code, 0) << html.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "r.html"));
    const auto json = run_command(cli() + " mesh " + q(dir / "x.step") + " --quiet --report " + q(dir / "r.json"));
    ASSERT_EQ(json.exit_code, 0) << json.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "r.json"));
    const auto files = std::distance(std::filesystem::directory_iterator(dir.path()), {});
    EXPECT_EQ(files, 3);  // x.step, r.html, r.json: no mesh file
}

}  // namespace
