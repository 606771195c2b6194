// Scale-free meshing (geom/working_scale.hpp): the working exponent, and the same block at
// 1e-6, 1 and 1e6 through STEP giving the same mesh up to the scale.
#include <BRepBuilderAPI_Transform.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/import/import.hpp"
#include "geom/import/step_write_occt.hpp"
#include "geom/mesh_file.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/working_scale.hpp"

namespace tubemesh::geom {
namespace {

namespace fs = std::filesystem;

TEST(WorkingScale, ExponentIsAMultipleOfThreeThatBringsTheDiagonalIntoOneToAThousand) {
    EXPECT_EQ(working_scale_exponent(29.4), 0);  // the dam block
    EXPECT_EQ(working_scale_exponent(19.6), 0);  // paper-ex2
    EXPECT_EQ(working_scale_exponent(514), 0);   // paper-ex3, in millimetres
    EXPECT_EQ(working_scale_exponent(1), 0);
    EXPECT_EQ(working_scale_exponent(999), 0);
    EXPECT_EQ(working_scale_exponent(1000), 3);
    EXPECT_EQ(working_scale_exponent(0.5), -3);
    EXPECT_EQ(working_scale_exponent(29.4e-6), -6);
    EXPECT_EQ(working_scale_exponent(29.4e6), 6);
    EXPECT_EQ(working_scale_exponent(0), 0);
    EXPECT_EQ(working_scale_exponent(std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(WorkingScale, LengthsGoThereAndBackWithExactPowers) {
    EXPECT_EQ(to_working(2.5e6, 6), 2.5);
    EXPECT_EQ(to_working(2.5e-6, -6), 2.5);
    EXPECT_EQ(from_working(2.5, 6), 2.5e6);
    EXPECT_EQ(from_working(2.5, -6), 2.5e-6);
    EXPECT_EQ(to_working(0.3, 0), 0.3);
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / "tubemesh_working_scale";
    fs::create_directories(dir);
    return dir / name;
}

// The preset's solid scaled by `factor`, written as STEP in metres and imported again.
Model imported_at(const std::string& preset, double factor) {
    const BuiltBlock block = build_block(preset_spec(preset));
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), factor);
    const TopoDS_Shape shape = BRepBuilderAPI_Transform(solid_of(block.model), scale, true).Shape();
    const fs::path path = scratch(preset + "_" + std::to_string(std::lround(std::log10(factor))) + ".step");
    write_step_shape(shape, path, "metre");
    return import_model(path);
}

struct Mesh {
    MeshRun run;
    int exponent = 0;
};

Mesh meshed_at(const std::string& preset, double factor) {
    const Model model = imported_at(preset, factor);
    MeshOptions options;
    options.threads = 2;
    return {mesh_model(model, options), model.scale_exponent()};
}

// The same counts, and every coordinate, S and St equal to 1e-9 of the block's diagonal after
// dividing by the scale.
void expect_same_up_to_scale(const Mesh& base, const Mesh& scaled, double factor) {
    const HybridMesh& a = base.run.result.mesh;
    const HybridMesh& b = scaled.run.result.mesh;
    ASSERT_EQ(a.point_count(), b.point_count());
    for (CellKind kind : {CellKind::Hex, CellKind::Pyramid, CellKind::Tet})
        EXPECT_EQ(a.cell_count(kind), b.cell_count(kind));
    EXPECT_EQ(a.face_count(FaceKind::Tri), b.face_count(FaceKind::Tri));
    EXPECT_EQ(a.face_count(FaceKind::Quad), b.face_count(FaceKind::Quad));
    const auto [x0, x1] = std::minmax_element(a.x.begin(), a.x.end());
    const auto [y0, y1] = std::minmax_element(a.y.begin(), a.y.end());
    const auto [z0, z1] = std::minmax_element(a.z.begin(), a.z.end());
    const double diagonal = std::hypot(*x1 - *x0, *y1 - *y0, *z1 - *z0);
    double worst = 0;
    for (index_t i = 0; i < a.point_count(); ++i)
        worst = std::max({worst, std::abs(b.x[i] / factor - a.x[i]), std::abs(b.y[i] / factor - a.y[i]),
                          std::abs(b.z[i] / factor - a.z[i])});
    EXPECT_LE(worst, 1e-9 * diagonal);
    EXPECT_NEAR(scaled.run.size / factor, base.run.size, 1e-9 * base.run.size);
    EXPECT_NEAR(scaled.run.sweep_size / factor, base.run.sweep_size, 1e-9 * base.run.sweep_size);
    EXPECT_NEAR(scaled.run.result.check.volume / (factor * factor * factor), base.run.result.check.volume,
                1e-9 * base.run.result.check.volume);
}

// 1e-6 and 1e6 read into the same working space: the same mesh up to the scale. At scale 1 the
// solid is read without scaling, so its coordinates differ from the working ones by rounding,
// which the tet step's insertion order can turn into a slightly different mesh: the same
// within a share `count_share` of the nodes.
void expect_scale_free(const std::string& preset, double count_share) {
    const Mesh small = meshed_at(preset, 1e-6);
    const Mesh large = meshed_at(preset, 1e6);
    EXPECT_EQ(small.exponent, -6);
    EXPECT_EQ(large.exponent, 6);
    expect_same_up_to_scale(small, large, 1e12);
    const Mesh base = meshed_at(preset, 1);
    EXPECT_EQ(base.exponent, 0);
    const double n = base.run.result.mesh.point_count();
    EXPECT_NEAR(small.run.result.mesh.point_count(), n, count_share * n);
    EXPECT_NEAR(base.run.size, small.run.size * 1e6, 1e-9 * base.run.size);
    EXPECT_NEAR(base.run.sweep_size, small.run.sweep_size * 1e6, 1e-9 * base.run.sweep_size);
}

TEST(WorkingScale, ArcPipeBlockAtAMillionthAndAMillionTimesGivesTheSameMesh) { expect_scale_free("arc-pipe", 0.01); }

#ifdef TUBEMESH_WORKING_SCALE_HEAVY
// The dam block: the 1e-6 and 1e6 reads differ by rounding too (19600 and 19622 nodes).
TEST(WorkingScale, DamBlockAtAMillionthAndAMillionTimesMeshesLikeAtScaleOne) {
    const Mesh base = meshed_at("paper-ex1", 1);
    EXPECT_EQ(base.exponent, 0);
    for (const double factor : {1e-6, 1e6}) {
        const Mesh scaled = meshed_at("paper-ex1", factor);
        EXPECT_EQ(scaled.exponent, factor < 1 ? -6 : 6);
        const double n = base.run.result.mesh.point_count();
        EXPECT_NEAR(scaled.run.result.mesh.point_count(), n, 0.01 * n);
        EXPECT_NEAR(scaled.run.size / factor, base.run.size, 1e-9 * base.run.size);
        EXPECT_NEAR(scaled.run.result.check.volume / (factor * factor * factor), base.run.result.check.volume,
                    1e-4 * base.run.result.check.volume);
    }
}
#endif

}  // namespace
}  // namespace tubemesh::geom
