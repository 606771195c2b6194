// geom::import_model and geom::write_step: formats, units, solid selection, healing and the
// errors a user sees. Files are written by OpenCASCADE in the test (tubemesh_occt).
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <GProp_GProps.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/model/face_names.hpp"
#include "geom/model/face_properties.hpp"
#include "geom/import/import.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/solid_check.hpp"
#include "geom/import/step_write.hpp"
#include "geom/import/step_write_occt.hpp"
#include "geom/working_scale.hpp"
#include "tests/support/error_of.hpp"

namespace tubemesh::geom {
namespace {

using tubemesh::testing::error_of;

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / "tubemesh_geom_import";
    fs::create_directories(dir);
    return dir / name;
}

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TopoDS_Shape box(double x0, double dx) { return BRepPrimAPI_MakeBox(gp_Pnt(x0, 0, 0), dx, 2, 3).Shape(); }

TEST(GeomImport, MissingFileSaysSo) {
    const std::string msg = error_of([] { import_model(scratch("no_such_file.step")); });
    EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

TEST(GeomImport, GarbageWithStepExtensionIsRejectedByTheReader) {
    const fs::path path = scratch("garbage.step");
    write_text(path, "this is not a STEP file\n");
    const std::string msg = error_of([&] { import_model(path); });
    EXPECT_NE(msg.find("not a readable STEP file"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
}

TEST(GeomImport, UnknownExtensionAndContentIsNotCad) {
    const fs::path path = scratch("notes.txt");
    write_text(path, "hello\n");
    const std::string msg = error_of([&] { import_model(path); });
    EXPECT_NE(msg.find("not a CAD file"), std::string::npos) << msg;
    EXPECT_NE(msg.find(".step"), std::string::npos) << "names the formats it reads: " << msg;
}

TEST(GeomImport, StepContentIsRecognisedWithoutExtension) {
    const fs::path step = scratch("box_for_sniff.step"), renamed = scratch("box_for_sniff.dat");
    write_step_shape(box(0, 1), step, "millimetre");
    fs::copy_file(step, renamed, fs::copy_options::overwrite_existing);
    EXPECT_EQ(import_model(renamed).report().format, "STEP");
}

TEST(GeomImport, TwoSolidsNeedSolidChoice) {
    BRep_Builder b;
    TopoDS_Compound two;
    b.MakeCompound(two);
    b.Add(two, box(0, 1));
    b.Add(two, box(5, 2));
    const fs::path path = scratch("two_solids.step");
    write_step_shape(two, path, "millimetre");

    const std::string msg = error_of([&] { import_model(path); });
    EXPECT_NE(msg.find("2 solids"), std::string::npos) << msg;
    EXPECT_NE(msg.find("--solid"), std::string::npos) << msg;

    const Model second = import_model(path, {.solid = 2});
    EXPECT_NEAR(second.volume(), 2 * 2 * 3, 1e-9);
    EXPECT_EQ(second.report().solids_in_file, 2);
    EXPECT_EQ(second.report().solid_index, 2);
    EXPECT_NEAR(import_model(path, {.solid = 1}).volume(), 1 * 2 * 3, 1e-9);

    const std::string range = error_of([&] { import_model(path, {.solid = 3}); });
    EXPECT_NE(range.find("--solid 3 is out of range"), std::string::npos) << range;
}

TopoDS_Shell box_faces(int skip) {
    BRep_Builder b;
    TopoDS_Shell shell;
    b.MakeShell(shell);
    int i = 0;
    for (TopExp_Explorer it(box(0, 1), TopAbs_FACE); it.More(); it.Next(), ++i)
        if (i != skip) b.Add(shell, it.Current());
    return shell;
}

TEST(GeomImport, OpenShellIsAnErrorThatSaysSo) {
    const fs::path path = scratch("open_shell.step");
    write_step_shape(box_faces(0), path, "millimetre");
    const std::string msg = error_of([&] { import_model(path); });
    EXPECT_NE(msg.find("no solid"), std::string::npos) << msg;
    EXPECT_NE(msg.find("open shell"), std::string::npos) << msg;
}

TEST(GeomImport, ClosedShellBecomesASolidWithANote) {
    const fs::path path = scratch("closed_shell.brep");
    TopoDS_Shell shell = box_faces(-1);
    shell.Closed(Standard_True);
    ASSERT_TRUE(BRepTools::Write(shell, path.c_str()));
    const Model m = import_model(path);
    EXPECT_NEAR(m.volume(), 6, 1e-9);
    ASSERT_FALSE(m.report().notes.empty());
    bool said = false;
    for (const std::string& n : m.report().notes) said |= n.find("sewn into 1 closed solid") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(GeomImport, BrepFileKeepsModelUnits) {
    const BuiltBlock built = build_block(preset_spec("straight-pipe"));
    const fs::path path = scratch("straight_pipe.brep");
    ASSERT_TRUE(BRepTools::Write(solid_of(built.model), path.c_str()));
    const Model m = import_model(path);
    EXPECT_EQ(m.report().format, "BREP");
    EXPECT_EQ(m.report().length_unit, "model units");
    EXPECT_LT(rel(m.volume(), *built.info.expected_volume), 1e-9);
    EXPECT_EQ(m.face_count(), 7);
}

TEST(GeomImport, IgesFileImportsWithItsUnit) {
    const BuiltBlock built = build_block(preset_spec("straight-pipe"));
    const fs::path path = scratch("straight_pipe.igs");
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", 1);  // 1: BRep entities, so the solid stays a solid
    writer.AddShape(solid_of(built.model));
    writer.ComputeModel();
    ASSERT_TRUE(writer.Write(path.c_str()));

    const Model m = import_model(path);
    EXPECT_EQ(m.report().format, "IGES");
    EXPECT_EQ(m.report().length_unit, "millimetre");
    EXPECT_LT(rel(m.volume(), *built.info.expected_volume), 1e-6);
    EXPECT_EQ(m.face_count(), 7);
}

TEST(GeomImport, IgesSurfacesAreSewnIntoASolid) {
    const fs::path path = scratch("box_faces.igs");
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", 0);  // 0: trimmed surfaces, no solid entity
    writer.AddShape(box(0, 1));
    writer.ComputeModel();
    ASSERT_TRUE(writer.Write(path.c_str()));
    const Model m = import_model(path);
    EXPECT_NEAR(m.volume(), 6, 1e-6);
    EXPECT_EQ(m.face_count(), 6);
    bool said = false;
    for (const std::string& n : m.report().notes) said |= n.find("6 faces were sewn into 1 closed solid") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(GeomImport, IgesInMetresIsNotRescaled) {
    const fs::path path = scratch("box_m.igs");
    IGESControl_Controller::Init();
    IGESControl_Writer writer("M", 1);
    writer.AddShape(box(0, 1));
    writer.ComputeModel();
    ASSERT_TRUE(writer.Write(path.c_str()));
    const Model m = import_model(path);
    EXPECT_EQ(m.report().length_unit, "metre");
    // The writer converted the 1 x 2 x 3 mm box to metres in the file; the reader keeps the
    // file's numbers instead of converting them back to millimetres. So small a box is held
    // at working scale, 1e3 times the file's (geom/working_scale.hpp).
    EXPECT_EQ(m.scale_exponent(), -3);
    const BoundingBox bb = m.bounds();
    EXPECT_NEAR(from_working(bb.max.x - bb.min.x, m.scale_exponent()), 0.001, 1e-9);
    EXPECT_NEAR(from_working(bb.max.z - bb.min.z, m.scale_exponent()), 0.003, 1e-9);
}

// The STEP round trip keeps the solid valid, its volume, its faces and the unit label, and
// coordinates are not rescaled (a 15 m block stays 15, not 15000).
void expect_round_trip(const std::string& preset, const std::string& unit) {
    SCOPED_TRACE(preset);
    const BuiltBlock built = build_block(preset_spec(preset));
    const fs::path path = scratch(preset + ".step");
    write_step(built.model, path);
    const Model m = import_model(path);
    EXPECT_EQ(m.report().length_unit, unit);
    EXPECT_TRUE(validity_problems(solid_of(m)).empty());
    EXPECT_EQ(m.face_count(), built.model.face_count());
    EXPECT_LT(rel(m.volume(), built.info.volume), 1e-6);
    const BoundingBox a = built.model.bounds(), b = m.bounds();
    EXPECT_NEAR(b.max.x - b.min.x, a.max.x - a.min.x, 1e-6 * (a.max.x - a.min.x));
    // The built block's face names come back from the file, each on the face it names.
    std::vector<std::string> written = face_names(built.model), read = m.report().face_names;
    const std::vector<std::string> sides = box_sides(m);
    ASSERT_EQ(read.size(), sides.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
        if (!read[i].empty()) {
            EXPECT_EQ(read[i], sides[i]) << "face_" << i + 1;
        }
    }
    std::sort(written.begin(), written.end());
    std::sort(read.begin(), read.end());
    EXPECT_EQ(read, written);
    EXPECT_GE(std::count_if(read.begin(), read.end(), [](const std::string& n) { return !n.empty(); }), 2);
}

// Import's positive-volume check integrates the volume once; the element budget's rough
// measures take that value instead of integrating again, and it is exactly what integrating
// the imported solid gives. A built model has none and gets the same figure computed.
TEST(GeomImport, RoughVolumeIsImportsOwnIntegration) {
    const BuiltBlock built = build_block(preset_spec("paper-ex2"));
    const fs::path path = scratch("rough-volume.step");
    write_step(built.model, path);
    const Model m = import_model(path);
    ASSERT_TRUE(m.impl().fixed_order_volume.has_value());
    GProp_GProps props;
    BRepGProp::VolumeProperties(solid_of(m), props);
    EXPECT_EQ(*m.impl().fixed_order_volume, props.Mass());
    EXPECT_EQ(rough_measures(m, {}).volume, props.Mass());
    EXPECT_LT(rel(props.Mass(), built.info.volume), 0.05);  // fixed order: a rough figure

    EXPECT_FALSE(built.model.impl().fixed_order_volume.has_value());
    GProp_GProps built_props;
    BRepGProp::VolumeProperties(solid_of(built.model), built_props);
    EXPECT_EQ(rough_measures(built.model, {}).volume, built_props.Mass());
}

TEST(GeomImport, StepRoundTripKeepsSolidVolumeAndUnits) {
    expect_round_trip("straight-pipe", "metre");
    expect_round_trip("arc-pipe", "metre");
    expect_round_trip("paper-ex1", "metre");
    expect_round_trip("paper-ex3", "millimetre");
    expect_round_trip("u-bend", "metre");
}

TEST(GeomImport, StepInInchesKeepsTheFileNumbers) {
    const fs::path path = scratch("box_inch.step");
    write_step_shape(box(0, 1), path, "inch");
    const Model m = import_model(path);
    EXPECT_EQ(m.report().length_unit, "inch");
    EXPECT_NEAR(m.volume(), 6, 1e-9);
}

TEST(GeomImport, StepWriteFailureLeavesNoFile) {
    const BuiltBlock built = build_block(preset_spec("straight-pipe"));
    const fs::path path = scratch("missing_dir") / "out.step";
    const std::string msg = error_of([&] { write_step(built.model, path); });
    EXPECT_NE(msg.find("cannot write"), std::string::npos) << msg;
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path.string() + ".tmp-tubemesh"));
}

// A prism on a bow-tie: its faces' wires cross themselves.
TopoDS_Shape bow_tie_prism() {
    BRepBuilderAPI_MakePolygon polygon(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0), gp_Pnt(2, 0, 0), gp_Pnt(0, 2, 0), Standard_True);
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(polygon.Wire(), Standard_True);
    return BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 1)).Shape();
}

TEST(GeomImport, InvalidSolidSaysWhichCheckFailed) {
    const fs::path path = scratch("bow_tie.brep");
    ASSERT_TRUE(BRepTools::Write(bow_tie_prism(), path.c_str()));
    const std::string msg = error_of([&] { import_model(path, {.heal = false}); });
    EXPECT_NE(msg.find("is not a valid solid ("), std::string::npos) << msg;
    EXPECT_NE(msg.find("face_"), std::string::npos) << "names the face: " << msg;
    EXPECT_NE(msg.find("SelfIntersectingWire"), std::string::npos) << msg;
    // Healing may or may not repair it; either way the outcome is a valid solid or a clear error.
    const std::string healed = error_of([&] {
        const Model m = import_model(path);
        EXPECT_TRUE(validity_problems(solid_of(m)).empty());
    });
    if (!healed.empty()) {
        EXPECT_NE(healed.find("is not a valid solid"), std::string::npos) << healed;
        EXPECT_NE(healed.find("heal"), std::string::npos) << healed;
    }
}

TEST(GeomImport, FacesAndEdgesAreNumberedFromOne) {
    const Model m = import_model([] {
        const fs::path path = scratch("numbered.step");
        write_step_shape(box(0, 1), path, "millimetre");
        return path;
    }());
    EXPECT_EQ(m.face_count(), 6);
    EXPECT_EQ(m.edge_count(), 12);
    EXPECT_EQ(Model::face_name(3), "face_3");
    EXPECT_EQ(Model::edge_name(12), "edge_12");
    EXPECT_EQ(face_id(m, face_of(m, 3)), 3);
    EXPECT_EQ(face_id(m, box(0, 1)), 0);
    EXPECT_TRUE(m.report().healing.empty()) << m.report().healing.front();
    // A file that names no face: no face names, and an imported box gets no box sides.
    for (const std::string& name : face_names(m)) EXPECT_EQ(name, "");
}

}  // namespace
}  // namespace tubemesh::geom
