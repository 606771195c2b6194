// Every value `tubemesh mesh` accepts for the ring's options meshes the paper's four-holes
// block and crankshaft into a mesh `tubemesh check` passes; a value it cannot mesh is refused
// before any work, naming the option, the value and the values that work, and the first of
// those meshes. test_cli_mesh_option_values_heavy (TUBEMESH_OPTION_VALUES_HEAVY, label heavy)
// holds only the heaviest value, 64 nodes around the four holes (about a minute and a half).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

using tubemesh::testing::built_preset;
using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::run_command;
using tubemesh::testing::TempDir;
namespace fs = std::filesystem;

struct Case {
    std::string preset, args;
};

// Meshes and passes `tubemesh check`; the run's error line in the failure message otherwise.
void expect_meshes(const fs::path& dir, const Case& c) {
    const fs::path out = dir / "out.msh";
    fs::remove(out);
    const auto r = run_command(cli() + " mesh " + q(built_preset(dir, c.preset)) + " " + c.args +
                               " --threads 2 --quiet -o " + q(out));
    ASSERT_EQ(r.exit_code, 0) << c.preset << " " << c.args << ": " << r.err;
    const auto check = run_command(cli() + " check " + q(out));
    EXPECT_EQ(check.exit_code, 0) << c.preset << " " << c.args << ": " << check.out << check.err;
    EXPECT_NE(check.out.find("valid and conforming"), std::string::npos) << c.preset << " " << c.args;
}

#ifndef TUBEMESH_OPTION_VALUES_HEAVY
// Options that shrink or stretch the ring's outer quads: the axial step follows them within
// what the pyramids on those quads take.
TEST(CliMeshOptionValues, RingOptionsMeshTheFourHolesBlockAndTheCrankshaft) {
    TempDir dir;
    const Case cases[] = {
        {"paper-ex2", "--layers 6"},       {"paper-ex2", "--layers 8"},
        {"paper-ex3", "--axial-aspect 16"}, {"paper-ex3", "--layers 8"},
        {"paper-ex3", "--circ 64"},
    };
    for (const Case& c : cases) expect_meshes(dir.path(), c);
}

// Outer quads shorter along the pipe than around it crowd their pyramids: refused at parse
// time with the range that works, whose lower end meshes.
TEST(CliMeshOptionValues, ShortAxialAspectRefusedWithAWorkingRange) {
    TempDir dir;
    const fs::path block = built_preset(dir.path(), "paper-ex2");
    std::string lowest;
    for (const std::string value : {"0.25", "0.5"}) {
        const auto r = run_command(cli() + " mesh " + q(block) + " --axial-aspect " + value + " -o " +
                                   q(dir / "out.msh"));
        EXPECT_EQ(r.exit_code, 2) << value;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(dir / "out.msh"));
        EXPECT_EQ(r.err.find("sweep size"), std::string::npos) << r.err;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(r.err, m, std::regex("--axial-aspect: must be a number from ([0-9.]+) to "
                                                           "[0-9.]+, got " + value)))
            << r.err;
        lowest = m[1];
    }
    expect_meshes(dir.path(), {"paper-ex2", "--axial-aspect " + lowest});
}

#else
// 64 nodes around the four holes: about 200 000 hexes and 100 000 pyramids.
TEST(CliMeshOptionValues, SixtyFourNodesAroundTheFourHoles) {
    TempDir dir;
    expect_meshes(dir.path(), {"paper-ex2", "--circ 64"});
}
#endif

}  // namespace
