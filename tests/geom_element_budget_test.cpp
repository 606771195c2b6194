// The element budget (geom/sizing/element_budget.hpp): its estimate is a lower bound of what the
// phases really make, kind by kind, and a run it refuses is refused before meshing with the
// smallest S that would fit — which then does fit.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cmath>
#include <fstream>
#include <string>

#include "engine/core/usable_memory.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/sizing/element_budget.hpp"
#include "geom/prepare.hpp"
#include "tests/support/error_of.hpp"

namespace {

using namespace tubemesh;

struct Case {
    const char* preset;
    double size;  // 0: the default
};

class ElementBudgetPreset : public ::testing::TestWithParam<Case> {};

TEST_P(ElementBudgetPreset, EstimateIsALowerBoundOfEveryKind) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec(GetParam().preset));
    geom::PrepareOptions po;
    po.sizing.size = GetParam().size;
    const geom::PreparedModel p = geom::prepare_model(block.model, po);
    MeshOptions mo;
    mo.size = GetParam().size;
    const PipelineResult r = run_pipeline(p.pipeline_input(), mo);
    const geom::ElementEstimate& e = p.estimate;
    const double tets = r.mesh.cell_count(CellKind::Tet), hexes = r.mesh.cell_count(CellKind::Hex);
    const double pyramids = r.mesh.cell_count(CellKind::Pyramid), triangles = r.mesh.face_count(FaceKind::Tri);
    std::printf("  %s: estimate tets %.0f / %.0f, triangles %.0f / %.0f, hexes %.0f / %.0f, pyramids %.0f / %.0f\n",
                GetParam().preset, e.tets, tets, e.triangles, triangles, e.hexes, hexes, e.pyramids, pyramids);
    EXPECT_GT(e.tets, 0.1 * tets);  // a bound that says something
    EXPECT_LE(e.tets, tets);
    EXPECT_LE(e.triangles, triangles);
    EXPECT_GT(e.hexes, 0);
    EXPECT_LE(e.hexes, hexes);
    EXPECT_LE(e.pyramids, pyramids);
    EXPECT_GT(e.quads, 0);
    EXPECT_LE(e.quads, r.mesh.face_count(FaceKind::Quad));
}

INSTANTIATE_TEST_SUITE_P(Presets, ElementBudgetPreset,
                         ::testing::Values(Case{"straight-pipe", 0}, Case{"arc-pipe", 0}, Case{"three-pipes", 0},
                                           Case{"paper-ex3", 40}),
                         [](const auto& info) {
                             std::string n = info.param.preset;
                             for (char& c : n)
                                 if (c == '-') c = '_';
                             return n;
                         });

TEST(ElementBudget, RefusedRunNamesTheSmallestSizeThatFitsAndThatSizeFits) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec("straight-pipe"));
    geom::PrepareOptions po;
    po.sizing.size = 0.2;
    po.budget.max_elements = 5000;
    const std::string message = tubemesh::testing::error_of([&] { geom::prepare_model(block.model, po); });
    ASSERT_NE(message.find("the mesh size S = 0.2 (given) is too small"), std::string::npos) << message;
    EXPECT_NE(message.find("--max-elements 5e+03"), std::string::npos) << message;
    const std::size_t at = message.find("give --size ");
    ASSERT_NE(at, std::string::npos) << message;
    const double fitting = std::stod(message.substr(at + 12));
    EXPECT_GT(fitting, 0.2);
    po.sizing.size = fitting;
    const geom::PreparedModel p = geom::prepare_model(block.model, po);
    EXPECT_LE(p.estimate.total(), 5000);
    EXPECT_GT(p.estimate.total(), 0.9 * 5000);  // the smallest that fits, to the bisection's 1 % and rounding
}

// A given St far too small: the message names it and the larger St that fits, which the sizing
// rules then accept and the budget then passes.
TEST(ElementBudget, TinySweepSizeIsBlamedOnTheRingsWithAStThatFits) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec("straight-pipe"));
    geom::PrepareOptions po;
    po.sizing.sweep_size = 1e-4;
    po.budget.max_elements = 1e6;
    const std::string message = tubemesh::testing::error_of([&] { geom::prepare_model(block.model, po); });
    EXPECT_NE(message.find("the sweep size St = 0.0001 (given) is too small"), std::string::npos) << message;
    const std::size_t at = message.find("give --sweep-size ");
    ASSERT_NE(at, std::string::npos) << message;
    po.sizing.sweep_size = std::stod(message.substr(at + 18));
    const geom::PreparedModel p = geom::prepare_model(block.model, po);
    EXPECT_LE(p.estimate.total(), 1e6);
}

// The figure in "at least N elements, more than LIMIT" is the one that exceeds the limit.
double elements_said(const std::string& message) {
    const std::size_t at = message.find("would have at least ");
    return at == std::string::npos ? 0 : std::stod(message.substr(at + 20));
}

// A pipe 0.025 (half its radius) from a face: the guard cuts St to 0.0074, and the rings then
// need more than 100 000 elements. The message compares a figure that really exceeds the limit,
// names the guard as St's source, and does not send the user to a larger St the rules refuse: it
// names the element limit that would do. (Closer, the ring would be under 0.1 r: the pipe would
// lose it, geometry_diagnosis.hpp.)
TEST(ElementBudget, RingsOfAGuardCutStAreRefusedWithoutCircularAdvice) {
    const geom::BuiltBlock block = geom::build_block(geom::parse_block_spec(
        R"({"check_clearance": false, "box": [4, 3, 2],
            "pipes": [{"path": "line", "diameter": 0.1, "points": [[0, 1.5, 0.075], [4, 1.5, 0.075]]}]})",
        "near face"));
    geom::PrepareOptions po;
    po.budget.max_elements = 1e5;
    const std::string message = tubemesh::testing::error_of([&] { geom::prepare_model(block.model, po); });
    EXPECT_GT(elements_said(message), 1e5) << message;
    EXPECT_NE(message.find("St = 0.00742187 (default: smallest tube diameter, cut by guard: boundary)"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find("give a larger --sweep-size"), std::string::npos) << message;
    EXPECT_NE(message.find("St cannot be larger here"), std::string::npos) << message;
    const std::size_t at = message.find("give --max-elements ");
    ASSERT_NE(at, std::string::npos) << message;
    po.budget.max_elements = std::stod(message.substr(at + 20));
    EXPECT_NO_THROW(geom::prepare_model(block.model, po));
}

TEST(ElementBudget, DefaultLimitIsWhatThisProcessMayUse) {
    const UsableMemory memory = usable_memory();
    ASSERT_GT(memory.bytes, 0);
    EXPECT_LE(memory.bytes, physical_memory_bytes());
    EXPECT_DOUBLE_EQ(geom::element_limit({}), memory.bytes / geom::kBytesPerElementAtLeast);
    geom::ElementBudget given;
    given.max_elements = 1234;
    EXPECT_DOUBLE_EQ(geom::element_limit(given), 1234);
    EXPECT_EQ(geom::element_limit_text(given), "--max-elements 1.23e+03");
    geom::ElementBudget read_before;  // what the CLI read before lowering its own limit
    read_before.memory = {1.5e9, "cgroup limit"};
    EXPECT_DOUBLE_EQ(geom::element_limit(read_before), 1e7);
    EXPECT_NE(geom::element_limit_text(read_before).find("1.4 GiB this process may use (cgroup limit"),
              std::string::npos)
        << geom::element_limit_text(read_before);
}

// `ulimit -v` binds when it is below the physical memory: the default budget follows it.
TEST(ElementBudget, AddressSpaceLimitBindsTheDefaultBudget) {
    rlimit before{};
    ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
    std::ifstream statm("/proc/self/statm");
    double pages = 0;
    statm >> pages;
    const double in_use = pages * double(sysconf(_SC_PAGE_SIZE));
    const double cap = std::floor(0.75 * physical_memory_bytes());
    if (in_use > 0.5 * cap || (before.rlim_cur != RLIM_INFINITY && double(before.rlim_cur) < cap))
        GTEST_SKIP() << "this process's address space leaves no room for the test";
    rlimit lowered = before;
    lowered.rlim_cur = static_cast<rlim_t>(cap);
    ASSERT_EQ(setrlimit(RLIMIT_AS, &lowered), 0);
    const UsableMemory memory = usable_memory();
    const double limit = geom::element_limit({});
    setrlimit(RLIMIT_AS, &before);
    if (cgroup_memory_limit_bytes() > 0 && cgroup_memory_limit_bytes() < cap) GTEST_SKIP() << "a cgroup limit binds";
    EXPECT_DOUBLE_EQ(memory.bytes, cap);
    EXPECT_EQ(memory.source, "address-space limit (ulimit -v)");
    EXPECT_DOUBLE_EQ(limit, cap / geom::kBytesPerElementAtLeast);
}

// The budget caps the real counts, not only the estimate: the crankshaft at S = 25 passes the
// estimate for 8000 elements (6.5e3) and makes about 1.6e4. At each limit the run either
// returns a mesh within it or is refused, as soon as the counts so far and the estimate of the
// stages left exceed it.
TEST(ElementCap, RunsAreRefusedOnTheirRealCountsAndNeverReturnMoreThanTheLimit) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec("paper-ex3"));
    const auto run = [&](double max_elements) {
        MeshOptions mo;
        mo.size = 25;
        mo.max_elements = max_elements;
        const geom::PreparedModel p = geom::prepare_model(block.model, geom::prepare_options(mo));
        return run_pipeline(p.pipeline_input(), mo);
    };
    const double made = element_count(run(0).mesh);
    ASSERT_GT(made, 8000);

    std::string early = tubemesh::testing::error_of([&] { run(8000); });
    EXPECT_NE(early.find("stage the mesh has "), std::string::npos) << early;
    EXPECT_NE(early.find("stopped before meshing further"), std::string::npos) << early;
    EXPECT_NE(early.find("more than --max-elements 8e+03"), std::string::npos) << early;

    // Past the stages' checks (about 9e3 with the estimate of the tets) but below what the
    // refinement holds on its way to about 1.3e4 tets: stopped there, before the optimisation.
    const std::string refining = tubemesh::testing::error_of([&] { run(12000); });
    EXPECT_NE(refining.find("while refining the tets: the mesh has "), std::string::npos) << refining;

        const std::string last = tubemesh::testing::error_of([&] { run(made - 1); });
    EXPECT_NE(last.find("the mesh has " + std::to_string(static_cast<long>(made)) + " elements"), std::string::npos)
        << last;
    EXPECT_EQ(element_count(run(made).mesh), made);
}

}  // namespace
