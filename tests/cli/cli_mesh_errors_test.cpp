// Every error of `tubemesh mesh` is one line on stderr naming the problem, exit code 2, and no
// output file (neither the mesh nor the report).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "geom/import/step_write_occt.hpp"
#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

using tubemesh::testing::run_command;
using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::TempDir;
namespace fs = std::filesystem;

TopoDS_Shape box(double x0, double dx) { return BRepPrimAPI_MakeBox(gp_Pnt(x0, 0, 0), dx, 2, 3).Shape(); }

class CliMeshErrors : public ::testing::Test {
protected:
    TempDir dir;
    fs::path pipe() { return tubemesh::testing::built_preset(dir.path(), "straight-pipe"); }
    // Runs `mesh IN -o out.msh --report out.json ARGS` and checks the common contract.
    void expect_error(const std::string& in, const std::string& args, const std::string& message,
                      const fs::path& output = {}) {
        const fs::path out = output.empty() ? dir / "out.msh" : output;
        const auto r = run_command(cli() + " mesh " + in + " -o " + q(out) + " --report " + q(dir / "out.json") +
                                   " " + args);
        EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << "want '" << message << "' in: " << r.err;
        EXPECT_FALSE(fs::exists(out));
        EXPECT_FALSE(fs::exists(dir / "out.json"));
        for (const auto& e : fs::directory_iterator(dir.path()))  // no temporary left either
            EXPECT_TRUE(e.path().extension() == ".step" || e.path().extension() == ".txt") << e.path();
    }
};

// A size for another unit (or a typo) that no machine could mesh: refused before meshing.
TEST_F(CliMeshErrors, SizeTooSmallForTheSolid) {
    expect_error(q(pipe()), "--size 1e-3 --sweep-size 5e-4", "the mesh size S = 0.001 (given) is too small");
}

TEST_F(CliMeshErrors, MoreElementsThanMaxElements) {
    expect_error(q(pipe()), "--max-elements 1000", "more than --max-elements 1e+03");
}

TEST_F(CliMeshErrors, MissingFile) { expect_error(q(dir / "nope.step"), "", "no such file"); }

TEST_F(CliMeshErrors, NotACadFile) {
    std::ofstream(dir / "notes.txt") << "hello\n";
    expect_error(q(dir / "notes.txt"), "", "not a CAD file");
}

TEST_F(CliMeshErrors, NoSolid) {
    BRep_Builder b;
    TopoDS_Shell shell;
    b.MakeShell(shell);
    int i = 0;
    for (TopExp_Explorer it(box(0, 1), TopAbs_FACE); it.More(); it.Next(), ++i)
        if (i != 0) b.Add(shell, it.Current());
    tubemesh::geom::write_step_shape(shell, dir / "open.step", "millimetre");
    expect_error(q(dir / "open.step"), "", "no solid");
}

TEST_F(CliMeshErrors, SeveralSolidsWithoutSolidOption) {
    BRep_Builder b;
    TopoDS_Compound two;
    b.MakeCompound(two);
    b.Add(two, box(0, 1));
    b.Add(two, box(5, 2));
    tubemesh::geom::write_step_shape(two, dir / "two.step", "millimetre");
    expect_error(q(dir / "two.step"), "", "choose one with --solid N (N from 1 to 2)");
    expect_error(q(dir / "two.step"), "", "or mesh them all as one conforming mesh with `tubemesh mesh --assembly`");
}

TEST_F(CliMeshErrors, NegativeSize) { expect_error(q(pipe()), "--size=-1", "--size: must be a positive number"); }

TEST_F(CliMeshErrors, NanSweepSize) {
    expect_error(q(pipe()), "--sweep-size nan", "--sweep-size: must be a positive number");
}

TEST_F(CliMeshErrors, SweepSizeNotBelowSize) {
    expect_error(q(pipe()), "--size 0.05 --sweep-size 0.1", "contradictory sizes");
}

TEST_F(CliMeshErrors, DefaultSweepSizeNotBelowGivenSize) {
    // St defaults to the pipe's diameter 0.1.
    expect_error(q(pipe()), "--size 0.08", "contradictory sizes");
}

TEST_F(CliMeshErrors, SweepSizeLargerThanThePipeAllows) {
    // The pipe's wall is 0.95 from the box's faces: a 0.9 ring plus its pyramids does not fit.
    // With the paper's one St (the local ring thins it near the faces instead).
    expect_error(q(pipe()), "--global-ring --size 2 --sweep-size 0.9", "too large for this model");
}

TEST_F(CliMeshErrors, OutputFolderMissing) {
    expect_error(q(pipe()), "", "does not exist", dir / "no_such_folder" / "out.msh");
}

TEST_F(CliMeshErrors, UnknownExtension) { expect_error(q(pipe()), "", "unknown mesh format", dir / "out.stl"); }

TEST_F(CliMeshErrors, ReportMustBeJson) {
    const auto r = run_command(cli() + " mesh " + q(pipe()) + " -o " + q(dir / "out.msh") + " --report " +
                               q(dir / "out.txt"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(".json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.msh"));
}

TEST_F(CliMeshErrors, HtmlReportMustBeHtml) {
    expect_error(q(pipe()), "--html " + q(dir / "report.htm"), "it must end in .html");
    EXPECT_FALSE(fs::exists(dir / "report.htm"));
}

TEST_F(CliMeshErrors, InputWithoutOutput) {
    const auto r = run_command(cli() + " mesh " + q(pipe()));
    EXPECT_EQ(r.exit_code, 2);
    for (const char* asked : {"-o", ".vtm", "--report", "--html"})
        EXPECT_NE(r.err.find(asked), std::string::npos) << asked << " in: " << r.err;
}

}  // namespace
