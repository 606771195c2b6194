// The block builders: every preset, the serpentine lift, random seeds and JSON specs give valid
// solids of the right shape; volumes match closed forms where they exist; bad specs give
// errors that name the pipe and the problem.
#include <BRepAdaptor_Surface.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "engine/core/types.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/centre_line.hpp"
#include "geom/builders/clearance.hpp"
#include "geom/builders/host_geometry.hpp"
#include "geom/builders/make_block.hpp"
#include "geom/builders/pipe_sweep.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/random_block.hpp"
#include "geom/builders/serpentine.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/import/import.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/solid_check.hpp"
#include "tests/support/error_of.hpp"

namespace tubemesh::geom {
namespace {

using tubemesh::testing::error_of;

constexpr double kPi = std::numbers::pi;
namespace fs = std::filesystem;

int host_faces(const HostSpec& h) { return h.kind == HostSpec::Kind::Box ? 6 : 3; }

// Every wall point's distance to the centre line, relative to the radius: how round the swept
// wall is. Sampled on the pipe solid's curved face before it is cut.
double max_wall_deviation(const PipeSpec& pipe, const HostSpec& host) {
    const CentreLine line = make_centre_line(pipe, host, 1);
    const TopoDS_Solid solid = sweep_pipe(line, pipe.diameter, 1);
    const double r = pipe.diameter / 2;
    double worst = 0;
    for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next()) {
        BRepAdaptor_Surface s(TopoDS::Face(it.Current()));
        if (s.GetType() == GeomAbs_Plane) continue;
        constexpr int kAround = 12, kAlong = 150;
        for (int i = 0; i < kAround; ++i)
            for (int j = 0; j <= kAlong; ++j) {
                const double u = s.FirstUParameter() + (s.LastUParameter() - s.FirstUParameter()) * i / kAround;
                const double v = s.FirstVParameter() + (s.LastVParameter() - s.FirstVParameter()) * j / kAlong;
                GeomAPI_ProjectPointOnCurve projection(s.Value(u, v), line.curve);
                if (projection.NbPoints() > 0) worst = std::max(worst, std::abs(projection.LowerDistance() - r) / r);
            }
    }
    return worst;
}

class Preset : public ::testing::TestWithParam<std::string> {};

TEST_P(Preset, BuildsOneValidSolidWithOneWallPerPipe) {
    const BlockSpec spec = preset_spec(GetParam());
    const BuiltBlock b = build_block(spec);
    EXPECT_TRUE(validity_problems(solid_of(b.model)).empty());
    EXPECT_EQ(b.model.face_count(), host_faces(spec.host) + static_cast<int>(spec.pipes.size()));
    EXPECT_EQ(b.info.pipe_count, static_cast<int>(spec.pipes.size()));
    EXPECT_EQ(b.info.pipe_diameters.size(), spec.pipes.size());
    EXPECT_EQ(b.info.name, GetParam());
    EXPECT_EQ(b.model.report().format, "built");
    EXPECT_GT(b.info.volume, 0);
    EXPECT_LT(b.info.volume, b.info.host_volume);
    if (b.info.expected_volume) {
        EXPECT_LT(std::abs(b.info.volume - *b.info.expected_volume) / *b.info.expected_volume, 1e-6)
            << "volume " << b.info.volume << " expected " << *b.info.expected_volume;
    }
}

TEST_P(Preset, WallsAreRoundToATenthOfAPercent) {
    const BlockSpec spec = preset_spec(GetParam());
    for (std::size_t i = 0; i < spec.pipes.size(); ++i)
        EXPECT_LT(max_wall_deviation(spec.pipes[i], spec.host), 1e-3) << "pipe " << i + 1;
}

INSTANTIATE_TEST_SUITE_P(All, Preset, ::testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const PresetInfo& p : preset_list()) names.push_back(p.name);
                             return names;
                         }()),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (char& c : n)
                                 if (c == '-') c = '_';
                             return n;
                         });

TEST(GeomBuilders, ClosedFormVolumesAreKnownForLinesAndArcs) {
    for (const char* name : {"straight-pipe", "oblique-pipe", "arc-pipe", "three-pipes"})
        EXPECT_TRUE(build_block(preset_spec(name)).info.expected_volume.has_value()) << name;
    for (const char* name : {"paper-ex1", "paper-ex3", "bent-pipe"})
        EXPECT_FALSE(build_block(preset_spec(name)).info.expected_volume.has_value()) << name;
    // The arc preset by hand: a quarter torus, R = 2.5, r = 0.05.
    const double r = 0.05;
    EXPECT_NEAR(*build_block(preset_spec("arc-pipe")).info.expected_volume, 4 * 4 * 2 - kPi * r * r * 2.5 * kPi / 2, 1e-12);
}

TEST(GeomBuilders, PaperPresetsHaveThePapersDimensions) {
    const BlockSpec ex1 = preset_spec("paper-ex1");
    EXPECT_EQ(ex1.host.size.x, 15);
    EXPECT_EQ(ex1.host.size.y, 25);
    EXPECT_EQ(ex1.host.size.z, 4);
    ASSERT_EQ(ex1.pipes.size(), 1u);
    EXPECT_EQ(ex1.pipes[0].diameter, 0.04);

    const BlockSpec ex2 = preset_spec("paper-ex2");
    EXPECT_EQ(ex2.host.size.x, 11);
    EXPECT_EQ(ex2.host.size.y, 12);
    EXPECT_EQ(ex2.host.size.z, 11);
    ASSERT_EQ(ex2.pipes.size(), 4u);
    for (const PipeSpec& p : ex2.pipes) EXPECT_EQ(p.diameter, 0.2);

    // The oil hole meets the journal's curved face at 30 degrees from its normal, at both ends.
    const BlockSpec ex3 = preset_spec("paper-ex3");
    EXPECT_EQ(ex3.host.kind, HostSpec::Kind::Cylinder);
    EXPECT_EQ(ex3.host.diameter, 295);
    ASSERT_EQ(ex3.pipes.size(), 1u);
    EXPECT_EQ(ex3.pipes[0].diameter, 12);
    const Vec3 a = ex3.pipes[0].points[0], b = ex3.pipes[0].points[1];
    const Vec3 d = normalized(b - a);
    for (const Vec3& end : {a, b}) {
        EXPECT_NEAR(std::hypot(end.x, end.y), 147.5, 1e-9);
        const Vec3 n = normalized(Vec3{end.x, end.y, 0});
        EXPECT_NEAR(std::acos(std::abs(dot(d, n))) * 180 / kPi, 30, 1e-9);
    }
}

// Length of a polyline with every corner rounded to radius R.
double filleted_length(const PipeSpec& p) {
    double len = 0;
    for (std::size_t i = 1; i < p.points.size(); ++i) len += norm(p.points[i] - p.points[i - 1]);
    for (std::size_t i = 1; i + 1 < p.points.size(); ++i) {
        const Vec3 u = normalized(p.points[i] - p.points[i - 1]), v = normalized(p.points[i + 1] - p.points[i]);
        const double turn = std::acos(std::clamp(dot(u, v), -1.0, 1.0));
        len += p.bend_radius * turn - 2 * p.bend_radius * std::tan(turn / 2);
    }
    return len;
}

TEST(GeomBuilders, SerpentineLiftMatchesItsReference) {
    const BlockSpec spec = preset_spec("serpentine-lift");
    EXPECT_EQ(spec.host.size.x, 20);
    EXPECT_EQ(spec.host.size.y, 15);
    EXPECT_EQ(spec.host.size.z, 3);
    ASSERT_EQ(spec.pipes.size(), 1u);
    const PipeSpec& pipe = spec.pipes[0];
    EXPECT_EQ(pipe.diameter, 0.032);
    for (const Vec3& p : pipe.points) EXPECT_EQ(p.z, 1.5);                    // mid-height
    EXPECT_EQ(pipe.points.front().x, 0);                                      // in through x = 0
    EXPECT_EQ(pipe.points.back().x, 0);                                       // and out through it
    EXPECT_NEAR(pipe.points.back().y - pipe.points.front().y, 9 * 1.5, 1e-12);  // 10 runs 1.5 apart

    // Volume: the removed pipe is pi r^2 times the filleted path length. The integration over
    // a 190 m B-spline wall is good to ~0.2% of the pipe's volume, not to 1e-6.
    const BuiltBlock b = build_block(spec);
    const double r = pipe.diameter / 2;
    const double removed = kPi * r * r * filleted_length(pipe);
    EXPECT_LT(std::abs((b.info.host_volume - b.info.volume) - removed) / removed, 1e-2);
}

TEST(GeomBuilders, SerpentineParametersAreChecked) {
    SerpentineParams p;
    p.outlet = "x+";  // opposite face: an odd number of runs
    const BlockSpec odd = serpentine_spec(p);
    EXPECT_EQ(odd.pipes[0].points.back().x, 20);
    EXPECT_EQ(odd.pipes[0].points.size() % 2, 0u);  // 2 per bend + 2 ends
    EXPECT_NO_THROW(build_block(odd));

    p.outlet = "y-";
    EXPECT_NE(error_of([&] { serpentine_spec(p); }).find("same face or on opposite faces"), std::string::npos);
    p.outlet = "x-";
    p.bend_radius = 1.0;
    EXPECT_NE(error_of([&] { serpentine_spec(p); }).find("at most half the spacing"), std::string::npos);
    p.bend_radius = 0.75;
    p.size = {20, 555555, 3};  // found by the fuzzer: 370,000 runs
    EXPECT_NE(error_of([&] { serpentine_spec(p); }).find("makes more than 1000 runs"), std::string::npos);
    p.bend_radius = 0.75;
    p.inlet = p.outlet = "z-";
    EXPECT_NE(error_of([&] { serpentine_spec(p); }).find("not a side face"), std::string::npos);
}

BlockSpec one_pipe(PathKind kind, std::vector<Vec3> points, double d = 0.1, double bend = 0) {
    BlockSpec s;
    s.name = "test";
    s.host.size = {4, 4, 4};
    PipeSpec p;
    p.kind = kind;
    p.points = std::move(points);
    p.diameter = d;
    p.bend_radius = bend;
    s.pipes.push_back(p);
    return s;
}

TEST(GeomBuilders, BadSpecsNameThePipeAndTheProblem) {
    auto msg = [](const BlockSpec& s) { return error_of([&] { build_block(s); }); };
    EXPECT_NE(msg(one_pipe(PathKind::Line, {{0, 2, 2}, {2, 2, 2}, {4, 2, 2}})).find("pipe 1: a line needs exactly 2 points"),
              std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Polyline, {{0, 1, 2}, {2, 1, 2}, {2, 4, 2}})).find("needs a bend_radius"),
              std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Polyline, {{0, 1, 2}, {2, 1, 2}, {2, 4, 2}}, 0.1, 2.5)).find("does not fit segment"),
              std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Polyline, {{0, 1, 2}, {2, 1, 2}, {2, 4, 2}}, 0.1, 0.051)).find("too small"),
              std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Line, {{1, 2, 2}, {4, 2, 2}})).find("does not start outside"), std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Arc, {{0, 1, 2}, {1, 1, 2}, {2, 1, 2}})).find("collinear"), std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Line, {{0, 2, 2}, {4, 2, 2}}, -1)).find("diameter must be positive"), std::string::npos);
    EXPECT_NE(msg(one_pipe(PathKind::Line, {{0, 2, 2}, {4, 2, 2}}, 4e-8)).find("pipe 1: its diameter 4e-08 is below 0.0001"),
              std::string::npos);  // OpenCASCADE's fixed tolerance, not a "bad path"
    // Leaves through the top and comes back in.
    EXPECT_NE(msg(one_pipe(PathKind::Polyline, {{0, 2, 2}, {1, 2, 2}, {1, 2, 5}, {3, 2, 5}, {3, 2, 2}, {4, 2, 2}}, 0.1, 0.3))
                  .find("leaves the block and enters it again"),
              std::string::npos);

    BlockSpec two = one_pipe(PathKind::Line, {{0, 2, 2}, {4, 2, 2}});
    two.pipes.push_back(two.pipes[0]);
    two.pipes[1].points = {{0, 2.12, 2}, {4, 2.12, 2}};
    EXPECT_NE(msg(two).find("pipe 1 and pipe 2 come within"), std::string::npos) << msg(two);

    EXPECT_NE(msg(one_pipe(PathKind::Line, {{0, 0.055, 2}, {4, 0.055, 2}})).find("of the block's boundary"),
              std::string::npos);
    EXPECT_NE(error_of([] { preset_spec("nope"); }).find("paper-ex1"), std::string::npos);
}

// Random blocks: 50 seeds, in five ctest tests of ten so that `ctest -j` runs them side by side.
class RandomSeeds : public ::testing::TestWithParam<int> {};

TEST_P(RandomSeeds, BuildValidSolidsWithClearPipes) {
    for (int seed = 10 * GetParam() + 1; seed <= 10 * GetParam() + 10; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const BlockSpec spec = random_block_spec(static_cast<std::uint64_t>(seed));
        ASSERT_GE(spec.pipes.size(), 1u);
        ASSERT_LE(spec.pipes.size(), 12u);
        BuiltBlock b{Model(nullptr), {}};
        ASSERT_NO_THROW(b = build_block(spec)) << block_spec_json(spec);
        EXPECT_EQ(b.model.face_count(), 6 + static_cast<int>(spec.pipes.size()));

        // The generator keeps 3 diameters (the larger of the two) between walls, measured on
        // samples one diameter apart; finer samples may find a little less.
        std::vector<PipeSamples> samples;
        for (const PipeSpec& p : spec.pipes)
            samples.push_back({sample_path(make_centre_line(p, spec.host, 1), p.diameter / 4), p.diameter / 2});
        for (std::size_t i = 0; i < samples.size(); ++i)
            for (std::size_t j = i + 1; j < samples.size(); ++j)
                EXPECT_GT(pipe_gap(samples[i], samples[j]), 2.5 * 2 * std::max(samples[i].radius, samples[j].radius))
                    << "pipes " << i + 1 << " and " << j + 1;
    }
}

INSTANTIATE_TEST_SUITE_P(Seeds1To50, RandomSeeds, ::testing::Range(0, 5));

TEST(GeomBuilders, RandomBlocksAreReproducible) {
    EXPECT_EQ(block_spec_json(random_block_spec(7)), block_spec_json(random_block_spec(7)));
    EXPECT_NE(block_spec_json(random_block_spec(7)), block_spec_json(random_block_spec(8)));
}

TEST(GeomBuilders, JsonSpecBuildsAndRoundTrips) {
    const std::string text = R"({
      "name": "two pipes", "unit": "metre", "box": [6, 5, 3],
      "pipes": [
        {"path": "line", "diameter": 0.1, "points": [[0, 2, 1], [6, 2, 1]]},
        {"path": "polyline", "diameter": 0.1, "bend_radius": 0.5, "points": [[0, 4, 1], [3, 4, 1], [3, 4, 3]]},
        {"path": "spline", "diameter": 0.1, "points": [[4.5, 0, 2], [4.6, 2, 2.2], [4.5, 5, 2]]}
      ]})";
    const BlockSpec spec = parse_block_spec(text, "inline.json");
    EXPECT_EQ(spec.name, "two pipes");
    EXPECT_EQ(spec.length_unit, "metre");
    ASSERT_EQ(spec.pipes.size(), 3u);
    EXPECT_EQ(spec.pipes[1].kind, PathKind::Polyline);
    const BuiltBlock b = build_block(spec);
    EXPECT_EQ(b.model.face_count(), 9);
    EXPECT_EQ(block_spec_json(parse_block_spec(block_spec_json(spec), "again.json")), block_spec_json(spec));

    const BlockSpec serp = parse_block_spec(R"({"serpentine": {"size": [10, 6, 2], "spacing": 1.5}})", "lift.json");
    EXPECT_EQ(serp.host.size.x, 10);
    EXPECT_EQ(serp.name, "lift");
}

TEST(GeomBuilders, JsonSpecErrorsSayWhere) {
    auto msg = [](const std::string& text) { return error_of([&] { parse_block_spec(text, "s.json"); }); };
    EXPECT_NE(msg("{").find("s.json: not valid JSON"), std::string::npos);
    EXPECT_NE(msg("{\"box\": [1e99999, 1, 1]}").find("s.json: not valid JSON"), std::string::npos);  // number overflow
    EXPECT_NE(msg(R"({"box": [1, 2, 3], "pipes": [], "pipe": 1})").find("unknown key 'pipe'"), std::string::npos);
    EXPECT_NE(msg(R"({"box": [1, 2], "pipes": [{}]})").find("s.json: box: expected [x, y, z]"), std::string::npos);
    EXPECT_NE(msg(R"({"box": [1, 2, 3], "pipes": [{"points": []}]})").find("pipes[0]: missing \"diameter\""),
              std::string::npos);
    EXPECT_NE(msg(R"({"box": [1, 2, 3], "pipes": [{"diameter": 1, "points": [[0, 0, "x"]]}]})")
                  .find("pipes[0].points[0][2]: expected a number"),
              std::string::npos);
    EXPECT_NE(msg(R"({"box": [1, 2, 3], "pipes": [{"path": "helix", "diameter": 1, "points": []}]})").find("unknown path 'helix'"),
              std::string::npos);
    EXPECT_NE(msg(R"({"pipes": [{"diameter": 1, "points": []}]})").find("exactly one of \"box\""), std::string::npos);
}

TEST(GeomBuilders, MakeBlockWritesAStepFileThatImports) {
    const fs::path dir = fs::path(::testing::TempDir()) / "tubemesh_make_block";
    fs::create_directories(dir);
    const BlockInfo info = make_block({.preset = "arc-pipe"}, dir / "arc.step");
    const Model m = import_model(dir / "arc.step");
    EXPECT_EQ(m.report().length_unit, "metre");
    EXPECT_LT(std::abs(m.volume() - *info.expected_volume) / *info.expected_volume, 1e-6);

    EXPECT_NO_THROW(make_block({.seed = 3}, dir / "seed3.step"));
    EXPECT_EQ(import_model(dir / "seed3.step").face_count(), 6 + static_cast<int>(random_block_spec(3).pipes.size()));

    EXPECT_NE(error_of([&] { make_block({.preset = "arc-pipe", .seed = 1}, dir / "x.step"); }).find("exactly one of"),
              std::string::npos);
    EXPECT_NE(error_of([&] { make_block({.spec = dir / "missing.json"}, dir / "x.step"); }).find("cannot open block spec"),
              std::string::npos);
}

}  // namespace
}  // namespace tubemesh::geom
