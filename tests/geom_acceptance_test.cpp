// Geometry acceptance on the blocks geom/builders makes: for every preset and 50 random seeds,
// tubes found = pipes built, (a) as built, (b) after a STEP write / import round trip through
// tubemesh's own writer and importer, and (c) after every closed (tube wall) face is split in
// two with ShapeUpgrade. Every tube discretises with end rings of equal node counts whose node 0
// sit at the same angle (1e-9 rad) in the end stations' frames; on the presets whose pipes are
// lines or circular arcs the centre line lies on the spec'd axis (1e-6 r straight, 1e-3 r arc)
// and node 0 of both rings is at the same angle around that axis in the pipe's own frame.
//
// The same source builds two executables: test_geom_acceptance (CI: every preset in all three
// variants, all 50 seeds as built, seeds 1-10 round-tripped and split) and, with
// TUBEMESH_ACCEPTANCE_HEAVY, test_geom_acceptance_heavy (label heavy: seeds 11-50 round-tripped
// and split). One ctest test per preset / seed and variant, so `ctest -j` spreads them.
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TopExp_Explorer.hxx>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/host_geometry.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/random_block.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/sizing/discretize.hpp"
#include "geom/import/import.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/step_write.hpp"

namespace tubemesh::geom {
namespace {

namespace fs = std::filesystem;
constexpr double kTwoPi = 2 * std::numbers::pi;

enum class Variant { Built, StepRoundTrip, SplitWalls };

const char* variant_name(Variant v) {
    switch (v) {
        case Variant::Built: return "Built";
        case Variant::StepRoundTrip: return "StepRoundTrip";
        case Variant::SplitWalls: return "SplitWalls";
    }
    return "?";
}

// The built block as the variant sees it.
Model variant_model(const BuiltBlock& block, Variant v, const std::string& tag) {
    switch (v) {
        case Variant::Built: return make_model(solid_of(block.model), block.model.report());
        case Variant::StepRoundTrip: {
            const fs::path dir = fs::path(::testing::TempDir()) / ("tubemesh_acceptance_" + std::to_string(::getpid()));
            fs::create_directories(dir);
            const fs::path path = dir / (tag + ".step");
            write_step(block.model, path);
            Model m = import_model(path);
            fs::remove_all(dir);
            return m;
        }
        case Variant::SplitWalls: {
            ShapeUpgrade_ShapeDivideClosed divide(solid_of(block.model));
            divide.SetNbSplitPoints(1);
            if (!divide.Perform()) throw Error("ShapeUpgrade_ShapeDivideClosed changed nothing");
            TopExp_Explorer it(divide.Result(), TopAbs_SOLID);
            if (!it.More()) throw Error("no solid after splitting");
            return make_model(TopoDS::Solid(it.Current()), block.model.report());
        }
    }
    throw Error("unknown variant");
}

std::string rejections(const TubeSearch& s) {
    std::string out;
    for (const auto& r : s.rejected) out += "  not a tube: " + r.reason + "\n";
    return out;
}

Vec3 minus_along(const Vec3& d, const Vec3& axis) { return d - dot(d, axis) * axis; }

// Angle of p around the station's tangent, from its reference direction.
double station_angle(const Vec3& p, const TubeStation& s) {
    const Vec3 q = minus_along(p - s.centre, s.tangent);
    return std::atan2(dot(q, cross(s.tangent, s.reference)), dot(q, s.reference));
}

double angle_gap(double a, double b) { return std::abs(std::remainder(a - b, kTwoPi)); }

// A line or circular-arc pipe of the spec, as an exact axis: distance of a point from it and
// the angle of a wall point around it in the pipe's own (fixed or torus) frame.
struct ExactAxis {
    bool arc = false;
    Vec3 origin, dir;      // line: a point and the unit direction
    Vec3 centre, normal;   // arc: circle centre and unit normal
    double bend = 0;       // arc: circle radius
    Vec3 e1, e2;           // line: a fixed frame across the axis
    double radius = 0;     // of the pipe

    double distance(const Vec3& p) const {
        if (!arc) return norm(minus_along(p - origin, dir));
        const Vec3 d = p - centre;
        return std::hypot(norm(minus_along(d, normal)) - bend, dot(d, normal));
    }
    double angle(const Vec3& p) const {
        if (!arc) {
            const Vec3 q = minus_along(p - origin, dir);
            return std::atan2(dot(q, e2), dot(q, e1));
        }
        const Vec3 d = p - centre;
        return std::atan2(dot(d, normal), norm(minus_along(d, normal)) - bend);
    }
};

std::optional<ExactAxis> exact_axis(const PipeSpec& p) {
    ExactAxis a;
    a.radius = p.diameter / 2;
    if (p.kind == PathKind::Line) {
        a.origin = p.points[0];
        a.dir = normalized(p.points[1] - p.points[0]);
        const Vec3 any = std::abs(a.dir.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        a.e1 = normalized(cross(a.dir, any));
        a.e2 = cross(a.dir, a.e1);
        return a;
    }
    if (p.kind == PathKind::Arc) {
        // Circumcentre of the three points.
        const Vec3 A = p.points[0], u = p.points[1] - A, v = p.points[2] - A;
        const Vec3 w = cross(u, v);
        const double w2 = dot(w, w);
        a.arc = true;
        a.centre = A + (1 / (2 * w2)) * (dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u));
        a.normal = normalized(w);
        a.bend = norm(A - a.centre);
        return a;
    }
    return std::nullopt;
}

// Everything acceptance asks of one block in one variant.
void check_block(const BuiltBlock& block, const BlockSpec& spec, Variant variant, const std::string& tag,
                 bool check_axes) {
    std::optional<Model> model_holder;
    try {
        model_holder.emplace(variant_model(block, variant, tag));
    } catch (const Error& e) {
        FAIL() << variant_name(variant) << " failed: " << e.what();
    }
    const Model& model = *model_holder;

    // Tubes found = pipes built, each of its pipe's radius.
    const TubeSearch found = find_tubes(model);
    ASSERT_EQ(static_cast<int>(found.tubes.size()), block.info.pipe_count)
        << rejections(found) << block_spec_json(spec);
    EXPECT_TRUE(found.rejected.empty()) << rejections(found);
    std::vector<double> radii, expected;
    for (const TubeInfo& t : found.tubes) {
        radii.push_back(t.radius_max);
        EXPECT_NEAR(t.radius_min, t.radius_max, 1e-3 * t.radius_max);
        // The builder sweeps each pipe into one wall face; splitting makes it two.
        EXPECT_EQ(t.faces.size(), variant == Variant::SplitWalls ? 2u : 1u);
    }
    for (double d : block.info.pipe_diameters) expected.push_back(d / 2);
    std::sort(radii.begin(), radii.end());
    std::sort(expected.begin(), expected.end());
    for (std::size_t i = 0; i < radii.size(); ++i) EXPECT_NEAR(radii[i], expected[i], 1e-3 * expected[i]);

    // End rings: equal node counts, node 0 at the same angle in the end stations' frames.
    const SizePlan plan = plan_sizes(model, found.tubes);
    DiscreteGeometry geometry;
    try {
        geometry = discretize(model, found.tubes, plan);
    } catch (const Error& e) {
        FAIL() << "discretize: " << e.what();
    }
    ASSERT_EQ(geometry.tubes.size(), found.tubes.size());
    for (std::size_t i = 0; i < geometry.tubes.size(); ++i) {
        SCOPED_TRACE("tube " + std::to_string(i + 1));
        const TubeData& t = geometry.tubes[i];
        ASSERT_GE(t.stations.size(), 2u);
        ASSERT_GE(t.ring1.size(), 4u);
        ASSERT_EQ(t.ring1.size(), t.ring2.size());
        const double a1 = station_angle(t.ring1[0], t.stations.front());
        const double a2 = station_angle(t.ring2[0], t.stations.back());
        EXPECT_LT(angle_gap(a1, a2), 1e-9) << "node 0 at " << a1 << " and " << a2 << " rad";
        EXPECT_LT(std::abs(a1), 1e-9);

        if (!check_axes) continue;
        // The pipe this tube is: the line or arc nearest its centre line (pipes are far apart).
        double best = std::numeric_limits<double>::infinity();
        std::optional<ExactAxis> axis;
        for (const PipeSpec& p : spec.pipes) {
            const std::optional<ExactAxis> a = exact_axis(p);
            if (!a) continue;
            double worst = 0;
            for (const TubeStation& s : t.stations) worst = std::max(worst, a->distance(s.centre));
            if (worst < best) best = worst, axis = a;
        }
        ASSERT_TRUE(axis.has_value());
        const double tol = (axis->arc ? 1e-3 : 1e-6) * axis->radius;
        std::ostringstream offsets;
        for (const TubeStation& s : t.stations) offsets << ' ' << axis->distance(s.centre) / axis->radius;
        EXPECT_LT(best, tol) << (axis->arc ? "arc" : "straight") << " centre line off its axis by " << best / axis->radius
                             << " r; station by station (r):" << offsets.str();
        // Splitting re-makes the wall's edges with ShapeFix's tolerances: the generator line
        // then reaches E2 a few 1e-8 rad off (paper-ex3: 3.5e-8).
        const double turn_tol = variant == Variant::SplitWalls ? 1e-7 : 1e-9;
        EXPECT_LT(angle_gap(axis->angle(t.ring1[0]), axis->angle(t.ring2[0])), turn_tol)
            << "node 0 of the rings at different angles around the pipe's own axis";
    }
}

[[maybe_unused]] std::string param_name(std::string n) {
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

// ---- presets ----
#ifndef TUBEMESH_ACCEPTANCE_HEAVY

struct PresetCase {
    std::string preset;
    Variant variant;
};

void PrintTo(const PresetCase& c, std::ostream* os) { *os << c.preset << " " << variant_name(c.variant); }

class AcceptancePreset : public ::testing::TestWithParam<PresetCase> {};

TEST_P(AcceptancePreset, TubesArePipesAndRingsAlign) {
    const BlockSpec spec = preset_spec(GetParam().preset);
    const BuiltBlock block = build_block(spec);
    bool exact = !spec.pipes.empty();
    for (const PipeSpec& p : spec.pipes) exact = exact && exact_axis(p).has_value();
    check_block(block, spec, GetParam().variant, param_name(GetParam().preset), exact);
}

std::vector<PresetCase> preset_cases() {
    std::vector<PresetCase> cases;
    for (const PresetInfo& p : preset_list())
        for (Variant v : {Variant::Built, Variant::StepRoundTrip, Variant::SplitWalls}) cases.push_back({p.name, v});
    return cases;
}

std::string preset_case_name(const ::testing::TestParamInfo<PresetCase>& info) {
    return param_name(info.param.preset) + "_" + variant_name(info.param.variant);
}
#endif

// ---- random seeds ----

struct SeedCase {
    int seed;
    Variant variant;
};

void PrintTo(const SeedCase& c, std::ostream* os) { *os << "seed " << c.seed << " " << variant_name(c.variant); }

class AcceptanceSeed : public ::testing::TestWithParam<SeedCase> {};

TEST_P(AcceptanceSeed, TubesArePipesAndRingsAlign) {
    const BlockSpec spec = random_block_spec(static_cast<std::uint64_t>(GetParam().seed));
    std::optional<BuiltBlock> block;
    try {
        block.emplace(build_block(spec));
    } catch (const Error& e) {
        FAIL() << "build: " << e.what() << "\n" << block_spec_json(spec);
    }
    check_block(*block, spec, GetParam().variant, "seed" + std::to_string(GetParam().seed), false);
}

std::vector<SeedCase> seed_cases(int first, int last, std::initializer_list<Variant> variants) {
    std::vector<SeedCase> cases;
    for (Variant v : variants)
        for (int s = first; s <= last; ++s) cases.push_back({s, v});
    return cases;
}

std::string seed_case_name(const ::testing::TestParamInfo<SeedCase>& info) {
    return "seed" + std::to_string(info.param.seed) + "_" + variant_name(info.param.variant);
}

#ifndef TUBEMESH_ACCEPTANCE_HEAVY
INSTANTIATE_TEST_SUITE_P(All, AcceptancePreset, ::testing::ValuesIn(preset_cases()), preset_case_name);
INSTANTIATE_TEST_SUITE_P(Built, AcceptanceSeed, ::testing::ValuesIn(seed_cases(1, 50, {Variant::Built})),
                         seed_case_name);
INSTANTIATE_TEST_SUITE_P(Changed, AcceptanceSeed,
                         ::testing::ValuesIn(seed_cases(1, 10, {Variant::StepRoundTrip, Variant::SplitWalls})),
                         seed_case_name);
#else
INSTANTIATE_TEST_SUITE_P(HeavyChanged, AcceptanceSeed,
                         ::testing::ValuesIn(seed_cases(11, 50, {Variant::StepRoundTrip, Variant::SplitWalls})),
                         seed_case_name);
#endif

}  // namespace
}  // namespace tubemesh::geom
