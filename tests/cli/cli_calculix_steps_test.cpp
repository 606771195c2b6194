// The .inp beyond the stress family's steady heat conduction, as CalculiX (Debian's ccx) runs
// it (tests/scripts/calculix_steps.py writes the decks and reads the results):
//  * --inp-family coupled on the dam block: a steady *COUPLED TEMPERATURE-DISPLACEMENT step
//    reproduces free thermal expansion at every node; coupled-abaqus writes C3D4T / C3D8T, which
//    ccx refuses (hence the name);
//  * --inp-family heat on the dam block: the *HEAT TRANSFER patch test on DC3D4 / DC3D8;
//  * --inp-pyramid c3d5: Abaqus only, in --help and in a warning when written;
//  * make-block --preset paper-ex1 through STEP keeps its face names (top, bottom, ...), and the
//    README's CalculiX deck runs on its mesh;
//  * a two-lift make-dam assembly: an element set per block and each block's top as a surface of
//    its own elements, over which *MODEL CHANGE removes and adds the upper lift.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_names.hpp"
#include "tests/support/mesh_io_samples.hpp"
#include "tests/support/outside_readers.hpp"
#include "tests/support/readme_blocks.hpp"

namespace tubemesh {
namespace {

using testing::read_text;
using testing::run_script;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The built-in dam block as .inp with `options`.
fs::path dam_inp(const TempDir& dir, const std::string& name, const std::string& options) {
    const fs::path inp = dir / name;
    const auto meshed = run_command(cli() + " mesh --quiet --threads 2 " + options + " -o " + q(inp));
    EXPECT_EQ(meshed.exit_code, 0) << meshed.err;
    return inp;
}

TEST(CalculixSteps, CoupledFamilyExpandsFreelyInACoupledStep) {
    TempDir dir;
    const fs::path inp = dam_inp(dir, "coupled.inp", "--inp-family coupled");
    const std::string text = read_text(inp);
    EXPECT_TRUE(contains(text, "*ELEMENT, TYPE=C3D8, ELSET=KIND_HEX\n"));
    EXPECT_FALSE(contains(text, "TYPE=C3D8T"));
    TempDir work;
    const json r = run_script("calculix_steps.py", {"coupled", inp.string(), work.path().string(), "left", "upstream",
                                                    "bottom"});
    std::cout << "dam block, coupled step: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("relative_u_error")) << r.dump();
    EXPECT_LT(r["t_error"].get<double>(), 1e-5);
    EXPECT_GT(r["max_displacement"].get<double>(), 0);
    EXPECT_LT(r["relative_u_error"].get<double>(), 1e-4);
}

// The Abaqus variant is what its name says: CalculiX stops at the unknown element type.
TEST(CalculixSteps, CoupledAbaqusFamilyIsRefusedByCalculix) {
    TempDir dir;
    const fs::path inp = dam_inp(dir, "abaqus.inp", "--inp-family coupled-abaqus");
    const std::string text = read_text(inp);
    EXPECT_TRUE(contains(text, "*ELEMENT, TYPE=C3D8T, ELSET=KIND_HEX\n"));
    testing::write_text(dir / "deck.inp", "*INCLUDE, INPUT=abaqus.inp\n*MATERIAL, NAME=C\n*CONDUCTIVITY\n2.5\n"
                                          "*SOLID SECTION, ELSET=EALL, MATERIAL=C\n*STEP\n*HEAT TRANSFER, STEADY "
                                          "STATE\n*BOUNDARY\ntop, 11, 11, 25.\n*END STEP\n");
    const auto ran = run_command("cd " + q(dir.path()) + " && OMP_NUM_THREADS=1 ccx -i deck 2>&1");
    EXPECT_TRUE(contains(ran.out, "unknown element type")) << ran.out;
}

TEST(CalculixSteps, HeatFamilyReproducesALinearTemperature) {
    TempDir dir;
    const fs::path inp = dam_inp(dir, "heat.inp", "--inp-family heat");
    EXPECT_TRUE(contains(read_text(inp), "*ELEMENT, TYPE=DC3D8, ELSET=KIND_HEX\n"));
    TempDir work;
    const json r = run_script("calculix_run.py", {"patch", inp.string(), work.path().string()});
    std::cout << "dam block, heat family patch test: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("relative_error")) << r.dump();
    EXPECT_LT(r["relative_error"].get<double>(), 1e-6);
}

TEST(CalculixSteps, FiveNodePyramidIsAbaqusOnly) {
    const auto help = run_command(cli() + " mesh --help");
    EXPECT_TRUE(contains(help.out, "c3d5 (the 5-node pyramid, stress family only: Abaqus only, CalculiX refuses it)"))
        << help.out;
    EXPECT_TRUE(contains(help.out, "coupled-abaqus (C3D4T/C3D8T: Abaqus only, CalculiX refuses them)")) << help.out;
    TempDir dir;
    const auto written = run_command(cli() + " mesh --threads 2 --inp-pyramid c3d5 -o " + q(dir / "p.inp"));
    ASSERT_EQ(written.exit_code, 0) << written.err;
    EXPECT_TRUE(contains(written.err, "holds C3D5 pyramids, which only Abaqus reads")) << written.err;
    EXPECT_TRUE(contains(read_text(dir / "p.inp"), "** C3D5 is for Abaqus: CalculiX has no 5-node pyramid"));
}

// The README deck names "top" and pipe_1's S6 faces: a block built by make-block and meshed from
// its STEP file has them as the built-in block does.
TEST(CalculixSteps, ReadmeDeckRunsOnAMadeBlock) {
    TempDir dir;
    const fs::path step = dir / "block.step";
    const auto made = run_command(cli() + " make-block --preset paper-ex1 -o " + q(step));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    EXPECT_TRUE(contains(read_text(step), "ADVANCED_FACE('top'"));
    const auto meshed = run_command(cli() + " mesh --quiet --threads 2 " + q(step) + " -o " + q(dir / "dam_block.inp"));
    ASSERT_EQ(meshed.exit_code, 0) << meshed.err;
    const std::string text = read_text(dir / "dam_block.inp");
    for (const char* side : {"top", "bottom", "upstream", "downstream", "left", "right"}) {
        EXPECT_TRUE(contains(text, std::string("*NSET, NSET=") + side + "\n")) << side;
        EXPECT_TRUE(contains(text, std::string("*SURFACE, NAME=") + side + ", TYPE=ELEMENT\n")) << side;
    }
    const std::string deck = testing::readme_block("calculix-deck");
    ASSERT_FALSE(deck.empty());
    testing::write_text(dir / "dam_heat.inp", deck);
    TempDir run;
    const json r = run_script("calculix_run.py", {"deck", (dir / "dam_heat.inp").string(),
                                                  (dir / "dam_block.inp").string(), run.path().string()});
    std::cout << "README deck on make-block paper-ex1: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("t_min")) << r.dump();
    EXPECT_GE(r["t_min"].get<double>(), 10.0 - 1e-5);
    EXPECT_LE(r["t_max"].get<double>(), 25.0 + 1e-5);
    EXPECT_LT(r["t_min"].get<double>(), 20.0);
}

TEST(CalculixSteps, LiftsAreBornByModelChange) {
    TempDir dir;
    const auto made = run_command(cli() + " make-dam --columns 1 --lifts 2 --width 4 --depth 3 --lift-height 1 "
                                          "--spacing 1 --diameter 0.05 --assembled --quiet -o " + q(dir.path()));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    const fs::path inp = dir / "section.inp";
    const auto meshed = run_command(cli() + " mesh --assembly --threads 2 " + q(dir / "section.step") + " -o " +
                                    q(inp) + " --report " + q(dir / "r.json"));
    ASSERT_EQ(meshed.exit_code, 0) << meshed.err;
    // The group table lists each block's top with its element set.
    EXPECT_TRUE(contains(meshed.out, "block_1_1_top  block_1_1  joint_block_1_1_block_1_2")) << meshed.out;
    const std::string text = read_text(inp);
    for (const char* set : {"*ELSET, ELSET=block_1_1\n", "*ELSET, ELSET=block_1_2\n", "*NSET, NSET=block_1_1_top\n",
                            "*SURFACE, NAME=block_1_1_top, TYPE=ELEMENT\n", "*SURFACE, NAME=block_1_2_top, TYPE=ELEMENT\n"})
        EXPECT_TRUE(contains(text, set)) << set;
    TempDir work;
    const json r = run_script("calculix_steps.py", {"lifts", inp.string(), work.path().string(), "block_1_1",
                                                    "block_1_2"});
    std::cout << "two lifts, the upper born after a day: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("steps")) << r.dump();
    const json& before = r["steps"][0];
    const json& after = r["steps"][1];
    // Day 1: the lower lift's top cools towards the film's 5; the removed lift is not computed.
    EXPECT_LT(before["lower_top"][0].get<double>(), 19.0);
    EXPECT_GT(before["lower_top"][0].get<double>(), 5.0);
    EXPECT_NEAR(before["upper_only"][0].get<double>(), 20.0, 1e-6);
    EXPECT_NEAR(before["upper_only"][1].get<double>(), 20.0, 1e-6);
    // Day 2: the upper lift is there and its top cools in turn.
    EXPECT_LT(after["upper_top"][0].get<double>(), 19.0);
    EXPECT_GT(after["upper_top"][0].get<double>(), 5.0);
}

}  // namespace
}  // namespace tubemesh
