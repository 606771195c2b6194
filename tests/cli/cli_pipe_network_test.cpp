// `tubemesh mesh --pipe-network`: the water in every pipe as a CalculiX network in the .inp and
// its films beside it (tests/scripts/calculix_network.py reads both and runs ccx):
//  * structure - every wall face has exactly one *FILM line, every water node is on the centre
//    line (a radius from the nearest wall node), the D elements are one chain from _water_in to
//    _water_out, and the network is in neither EALL nor NALL: on the dam block, a dam section
//    meshed as an assembly with a pipe across the column joint, and (heavy) the serpentine lift;
//  * CalculiX - a straight pipe through concrete held at T_c gives the outlet temperature
//    T_c - (T_c - T_in) exp(-h pi D L / (m c_p)) within 1 % of the rise; on the dam block the
//    water carries away what crosses the wall faces and what leaves through the top; reversing
//    the flow in a symmetric block mirrors the water temperatures;
//  * the options: each error is exit 2 and no file;
//  * the README's transient deck of two lifts as written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_names.hpp"
#include "tests/support/outside_readers.hpp"

namespace tubemesh {
namespace {

using testing::run_script;

json network(std::vector<std::string> args) { return run_script("calculix_network.py", std::move(args)); }

// `tubemesh make-block --preset NAME` into dir/NAME.step.
fs::path preset_step(const TempDir& dir, const std::string& name) {
    const fs::path step = dir / (name + ".step");
    const auto made = run_command(cli() + " make-block --preset " + name + " -o " + q(step));
    EXPECT_EQ(made.exit_code, 0) << made.err;
    return step;
}

// `tubemesh mesh IN --pipe-network OPTIONS -o dir/NAME.inp` (IN empty: the built-in dam block).
fs::path mesh_network(const TempDir& dir, const std::string& in, const std::string& name,
                      const std::string& options = "") {
    const fs::path inp = dir / (name + ".inp");
    const auto meshed = run_command(cli() + " mesh --quiet --threads 2 --pipe-network " + options + " " + in + " -o " +
                                    q(inp));
    EXPECT_EQ(meshed.exit_code, 0) << meshed.err;
    EXPECT_TRUE(fs::exists(dir / (name + ".films.inp")));
    return inp;
}

void expect_structure(const fs::path& inp, double radius, std::size_t pipes) {
    const json r = network({"structure", inp.string(), std::to_string(radius)});
    std::cout << inp.filename().string() << " network: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("pipes")) << r.dump();
    EXPECT_EQ(r["pipes"].size(), pipes);
    for (const auto& [name, p] : r["pipes"].items()) {
        EXPECT_GT(p["faces"].get<int>(), 0) << name;
        EXPECT_EQ(p["film_lines"], p["faces"]) << name;
        EXPECT_EQ(p["missing"].get<int>(), 0) << name;
        EXPECT_EQ(p["extra"].get<int>(), 0) << name;
        EXPECT_EQ(p["repeated"].get<int>(), 0) << name;
        EXPECT_EQ(p["in_nall"].get<int>(), 0) << name;
        EXPECT_EQ(p["outside_water"].get<int>(), 0) << name;
        EXPECT_LT(p["worst_radius_error"].get<double>(), 0.01) << name;
        EXPECT_EQ(p["chain"], "one chain") << name;
        EXPECT_GT(p["segments"].get<int>(), 1) << name;
    }
}

#ifndef TUBEMESH_PIPE_NETWORK_HEAVY

TEST(PipeNetwork, DamBlockStructure) {
    TempDir dir;
    expect_structure(mesh_network(dir, "", "dam"), 0.02, 1);
}

// make-dam's 2 x 1 section with a crossing pipe, meshed as an assembly: the crossing pipe is
// one network from one outer face to the other.
TEST(PipeNetwork, AssemblyPipeAcrossAJointIsOneNetwork) {
    TempDir dir;
    const auto made = run_command(cli() +
                                  " make-dam --columns 2 --lifts 1 --width 4 --depth 3 --lift-height 1 --spacing 1 "
                                  "--diameter 0.05 --crossing-pipes 1 --assembled --quiet -o " +
                                  q(dir.path()));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    expect_structure(mesh_network(dir, "--assembly " + q(dir / "section.step"), "section"), 0.025, 3);
}

// Concrete held at T_c: the water warms as T_c - (T_c - T_in) exp(-h pi D L / (m c_p)). 32
// nodes around the pipe, so the wall's polygon has the circle's perimeter within 0.2 %
// (8 nodes: 2.5 % short, which the formula does not know).
TEST(PipeNetwork, StraightPipeOutletMatchesTheFormula) {
    TempDir dir;
    const fs::path inp = mesh_network(dir, q(preset_step(dir, "straight-pipe")), "pipe", "--circ 32");
    TempDir work;
    // h pi D L / (m c_p) = 2000 pi 0.1 4 / (1 4186) = 0.60
    const json r = network({"fixed", inp.string(), work.path().string(), "30", "10", "1.0", "2000", "4", "0.1"});
    std::cout << "straight pipe, concrete at 30, water in at 10: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("t_out")) << r.dump();
    EXPECT_LT(r["error_of_rise"].get<double>(), 0.01);
    EXPECT_LT(r["error_of_t_out"].get<double>(), 0.01);
}

TEST(PipeNetwork, DamBlockEnergyBalance) {
    TempDir dir;
    const fs::path inp = mesh_network(dir, "", "dam");
    TempDir work;
    const json r = network({"balance", inp.string(), work.path().string(), "25", "10", "0.3"});
    std::cout << "dam block, top at 25, water in at 10, 0.3 kg/s: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("water_heat")) << r.dump();
    EXPECT_GT(r["t_out"].get<double>(), 10.0);
    EXPECT_LT(r["error_wall"].get<double>(), 0.01);
    EXPECT_LT(r["error_fixed"].get<double>(), 0.01);
}

// The straight-pipe block is symmetric about x = 2: water entering at x = 4 has at 4 - x the
// temperature water entering at 0 has at x.
TEST(PipeNetwork, ReversedFlowMirrorsTheWaterTemperatures) {
    TempDir dir;
    const fs::path step = preset_step(dir, "straight-pipe");
    const fs::path forward = mesh_network(dir, q(step), "forward");
    const fs::path reversed = mesh_network(dir, q(step), "reversed", "--reverse-flow 1");
    TempDir work;
    const json r = network({"mirror", forward.string(), reversed.string(), work.path().string(), "30", "10", "0.05"});
    std::cout << "straight pipe, flow one way and the other: " << r.dump() << "\n";
    ASSERT_TRUE(r.contains("error")) << r.dump();
    EXPECT_EQ(r["matched"], r["nodes"]);
    EXPECT_GT(r["nodes"].get<int>(), 4);
    EXPECT_GT(r["rise"].get<double>(), 0.5);
    EXPECT_LT(r["error"].get<double>(), 0.01);
    EXPECT_GT(r["inlets"][1].get<double>() - r["inlets"][0].get<double>(), 3.9);  // enters at x = 4
}

void expect_refused(const std::string& options, const std::string& says) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh --quiet " + options + " -o " + q(dir / "dam.inp"));
    EXPECT_EQ(r.exit_code, 2) << options;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "dam.inp")) << options;
    EXPECT_FALSE(fs::exists(dir / "dam.films.inp")) << options;
}

TEST(PipeNetwork, OptionErrorsAreExit2AndNoFile) {
    expect_refused("--film-coefficient 100", "--pipe-network");
    expect_refused("--reverse-flow 1", "--pipe-network");
    expect_refused("--pipe-network --film-coefficient -5", "--film-coefficient");
    expect_refused("--pipe-network --reverse-flow 0", "pipes are numbered from 1");
    expect_refused("--pipe-network --reverse-flow 2", "no pipe_2");
    TempDir dir;
    const auto r = run_command(cli() + " mesh --quiet --pipe-network -o " + q(dir / "dam.msh"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(".inp"), std::string::npos) << r.err;
}

// A solid without pipes (a dam's foundation block) has no water: no network, no *FILM.
TEST(PipeNetwork, ASolidWithoutPipesHasNoWater) {
    TempDir dir;
    std::ofstream(dir / "plain.json") << R"({"name": "plain", "unit": "metre", "box": [1, 1, 1], "pipes": []})";
    const fs::path step = dir / "plain.step";
    ASSERT_EQ(run_command(cli() + " make-block --spec " + q(dir / "plain.json") + " -o " + q(step)).exit_code, 0);
    const fs::path inp = mesh_network(dir, q(step), "plain");
    std::ifstream in(inp), films(dir / "plain.films.inp");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string film_text((std::istreambuf_iterator<char>(films)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("TYPE=D"), std::string::npos);
    EXPECT_EQ(film_text.find("*FILM"), std::string::npos);
}

// The deck between the README's "pipe-cooling-deck" markers, as written, on the section its
// commands make: the upper pipe's water leaves as it came until its lift is placed, then warms.
TEST(PipeNetwork, TheReadmeTransientDeckRunsAsWritten) {
    std::ifstream readme(std::string(TUBEMESH_SOURCE_DIR) + "/README.md");
    const std::string s((std::istreambuf_iterator<char>(readme)), std::istreambuf_iterator<char>());
    const std::string begin = "<!-- pipe-cooling-deck -->\n```\n", end = "```\n<!-- /pipe-cooling-deck -->";
    const std::size_t from = s.find(begin), to = s.find(end);
    ASSERT_NE(from, std::string::npos) << "README has no pipe-cooling-deck block";
    ASSERT_NE(to, std::string::npos);
    TempDir dir;
    std::ofstream(dir / "lifts_heat.inp") << s.substr(from + begin.size(), to - from - begin.size());
    const auto made = run_command(cli() +
                                  " make-dam --columns 1 --lifts 2 --width 4 --depth 3 --lift-height 1 --spacing 1 "
                                  "--diameter 0.05 --assembled --quiet -o " +
                                  q(dir / "lifts"));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    const fs::path inp = mesh_network(dir, "--assembly " + q(dir / "lifts" / "section.step"), "section");
    TempDir work;
    const json r = network({"transient", (dir / "lifts_heat.inp").string(), inp.string(), work.path().string()});
    ASSERT_TRUE(r.contains("times")) << r.dump();
    const auto& times = r["times"];
    const auto& lower = r["outlets"]["pipe_1"];
    const auto& upper = r["outlets"]["pipe_2"];
    ASSERT_EQ(lower.size(), times.size());
    ASSERT_EQ(upper.size(), times.size());
    std::cout << "README transient deck, outlet water temperature per day:\n";
    double lower_peak = 0, upper_peak = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const double day = times[i].get<double>() / 86400;
        std::cout << "  day " << day << ": pipe_1 " << lower[i] << ", pipe_2 " << upper[i] << "\n";
        if (day <= 7) {
            EXPECT_NEAR(upper[i].get<double>(), 10.0, 1e-6) << "day " << day;
        }
        lower_peak = std::max(lower_peak, lower[i].get<double>());
        upper_peak = std::max(upper_peak, upper[i].get<double>());
    }
    EXPECT_NEAR(times.back().get<double>(), 14 * 86400.0, 1.0);
    EXPECT_GT(lower_peak, 11.0);
    EXPECT_GT(upper_peak, 11.0);
    EXPECT_LT(std::max(lower_peak, upper_peak), 15.0);  // 1500 W/m3 fading over days, cooled from the start
}

#else

TEST(PipeNetwork, SerpentineLiftStructure) {
    TempDir dir;
    expect_structure(mesh_network(dir, q(preset_step(dir, "serpentine-lift")), "lift"), 0.016, 1);
}

#endif

}  // namespace
}  // namespace tubemesh
