// Nothing lost: an interrupted or failing `tubemesh mesh` leaves no temporary file behind and
// every file that existed before it intact; options are refused at parse time in plain numbers.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::run_command;
using tubemesh::testing::TempDir;
namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

struct Option {
    std::string args, message;
};

// Each is refused before any work, with the allowed values in plain numbers.
TEST(CliMeshOptions, RefusedAtParseTimeInPlainNumbers) {
    const Option cases[] = {
        {"--max-elements nan", "--max-elements: must be a positive number, got nan"},
        {"--max-elements 0", "--max-elements: must be a positive number, got 0"},
        {"--circ 3", "--circ: must be a whole number from 4 to 4096, got 3"},
        {"--layers 64", "--layers: must be a whole number from 1 to 8, got 64"},
        {"--layers 2.5", "--layers: must be a whole number from 1 to 8, got 2.5"},
        {"--threads 0", "--threads: must be a whole number from 1 to 4096, got 0"},
        {"--size inf", "--size: must be a positive number, got inf"},
        {"--sweep-size=-1", "--sweep-size: must be a positive number, got -1"},
        {"--gradation 0.5", "--gradation: must be a number from 1 to 4, got 0.5"},
        {"--axial-aspect nan", "--axial-aspect: must be a number from 1 to 16, got nan"},
        {"--tet-relax 17", "--tet-relax: must be a whole number from 0 to 16, got 17"},
    };
    TempDir dir;
    for (const Option& c : cases) {
        const auto r = run_command(cli() + " mesh -o " + q(dir / "out.msh") + " " + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_EQ(r.err, "tubemesh: " + c.message + "\n") << c.args;
        EXPECT_TRUE(r.out.empty()) << c.args << ": " << r.out;
    }
    EXPECT_TRUE(names_in(dir.path()).empty());
}

// --circ beyond what memory holds names --circ, not St.
TEST(CliMeshOptions, TooManyNodesAroundNamesCirc) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh -o " + q(dir / "out.msh") + " --circ 4096");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--circ 4096 puts too many nodes around the tubes"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("default: default:"), std::string::npos) << r.err;
}

// Outputs that would be one file are refused before any work, with both names on one line:
// the same file twice, a file in the folder of a .vtm's parts (which existed from an earlier run),
// two .vtm files sharing that folder.
TEST(CliMeshOptions, OutputsThatAreOneFileAreRefusedBeforeMeshing) {
    TempDir dir;
    fs::create_directory(dir / "a");
    fs::create_directory(dir / "sub");
    const std::string vtm = (dir / "a.vtm").string(), part = (dir / "a" / "volume_tets.vtu").string();
    const std::string inside = "cannot write '" + part + "': it is inside '" + (dir / "a").string() + "', where '" +
                               vtm + "' writes its parts";
    const Option cases[] = {
        {"-o " + q(vtm) + " -o " + q(part), inside},
        {"-o " + q(part) + " -o " + q(vtm), inside},
        {"-o " + q(vtm) + " --html " + q(dir / "a" / "page.html"), "where '" + vtm + "' writes its parts"},
        {"-o " + q(dir / "b.msh") + " -o " + q(dir / "sub" / ".." / "b.msh"),
         "cannot write '" + (dir / "sub" / ".." / "b.msh").string() + "': it is the same file as '" +
             (dir / "b.msh").string() + "'"},
        {"-o " + q(vtm) + " -o " + q(dir / "a.VTM"),
         "cannot write '" + (dir / "a.VTM").string() + "': '" + vtm + "' writes its parts to the same folder"},
    };
    for (const Option& c : cases) {
        const auto r = run_command(cli() + " mesh " + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(r.out.empty()) << c.args << ": " << r.out;
    }
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"a", "sub"}));
    EXPECT_TRUE(fs::is_empty(dir / "a"));
}

// Hexes past the analysis limit are not silent: the warning names the layers as the cause.
TEST(CliMeshOptions, ManyLayersWarnOfThinHexes) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh --layers 6 -o " + q(dir / "out.msh"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("tubemesh: warning: the worst hexahedron has condition number"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("with 6 layers across a ring"), std::string::npos) << r.err;
    const auto two = run_command(cli() + " mesh --layers 2 -o " + q(dir / "out.msh"));
    EXPECT_EQ(two.err.find("hexahedron"), std::string::npos) << two.err;
}

class CliMeshSafety : public ::testing::Test {
protected:
    TempDir dir;
    fs::path pipe() { return tubemesh::testing::built_preset(dir.path(), "straight-pipe"); }
};

// A disk that fills at the third output (a file-size limit between the sizes of the outputs):
// the run fails, the first target keeps the user's earlier file, and nothing else is left.
TEST_F(CliMeshSafety, FailingThirdOutputKeepsEveryEarlierFile) {
    const fs::path in = pipe();
    TempDir sizes;
    ASSERT_EQ(run_command(cli() + " mesh " + q(in) + " --quiet -o " + q(sizes / "a.msh") + " -o " +
                          q(sizes / "a.inp") + " -o " + q(sizes / "a.vtu"))
                  .exit_code,
              0);
    const auto small = std::max(fs::file_size(sizes / "a.msh"), fs::file_size(sizes / "a.inp"));
    const auto large = fs::file_size(sizes / "a.vtu");
    ASSERT_LT(small, large);  // the .vtu (base64) is the one that will not fit

    const std::string earlier = "a mesh the user made before\n";
    std::ofstream(dir / "pre.msh") << earlier;
    const std::vector<std::string> before = names_in(dir.path());
    const auto r = run_command("prlimit --fsize=" + std::to_string((small + large) / 2) + " " + cli() + " mesh " +
                               q(in) + " --quiet -o " + q(dir / "pre.msh") + " -o " + q(dir / "b.inp") + " -o " +
                               q(dir / "c.vtu") + " --report " + q(dir / "r.json"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("cannot write '" + (dir / "c.vtu").string() + "'"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(dir / "pre.msh"), earlier);
    EXPECT_EQ(names_in(dir.path()), before);
}

// A signal while the outputs are being written (sent when the first temporary appears, with
// three files still to write and rename): the process ends by that signal, no temporary is
// left, no target appears and the file that was there before is intact.
void interrupt_while_writing(const fs::path& dir, int signal_number) {
    const std::string earlier = "kept\n";
    std::ofstream(dir / "y.vtu") << earlier;
    const std::vector<std::string> before = names_in(dir);

    // The dam block (no input): big enough that writing three files takes a while.
    const auto run = tubemesh::testing::signal_when_created(
        {TUBEMESH_CLI, "mesh", "--quiet", "-o", (dir / "x.msh").string(), "-o", (dir / "y.vtu").string(), "-o",
         (dir / "z.inp").string()},
        dir, ".x.msh.tmp-", signal_number);
    ASSERT_TRUE(run.sent);
    EXPECT_TRUE(WIFSIGNALED(run.status) && WTERMSIG(run.status) == signal_number) << "status " << run.status;
    EXPECT_EQ(names_in(dir), before);
    EXPECT_EQ(read_file(dir / "y.vtu"), earlier);
}

// A run that outgrows its memory (here a 160 MiB address-space limit on a 210 MB run) ends
// with a message, exit 2 and no file, not with the kernel's out-of-memory killer.
TEST_F(CliMeshSafety, OutOfMemoryEndsWithAMessage) {
    const auto r = run_command("prlimit --as=" + std::to_string(160 << 20) + " " + cli() + " mesh --threads 2 --size 0.25 -o " +
                               q(dir / "out.msh"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("tubemesh: out of memory: the run needed more than the 0.156 GiB", 0), 0u) << r.err;
    EXPECT_TRUE(names_in(dir.path()).empty());
}

// The hidden temporaries in `dir`.
std::vector<std::string> temporaries_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const std::string& n : names_in(dir))
        if (n.find(".tmp-") != std::string::npos) names.push_back(n);
    return names;
}

// kill -9 while the outputs are written leaves their temporaries; the next run writing those
// files removes them, but not the temporary of a live process (this test's, standing for a
// concurrent run).
TEST_F(CliMeshSafety, TemporariesOfAKilledRunGoWithTheNextRun) {
    const auto killed = tubemesh::testing::signal_when_created(
        {TUBEMESH_CLI, "mesh", "--quiet", "-o", (dir / "x.msh").string(), "-o", (dir / "y.vtu").string()}, dir.path(),
        ".y.vtu.tmp-", SIGKILL);
    ASSERT_TRUE(killed.sent);
    ASSERT_TRUE(WIFSIGNALED(killed.status) && WTERMSIG(killed.status) == SIGKILL) << killed.status;
    ASSERT_EQ(temporaries_in(dir.path()).size(), 2u);
    const std::string live = ".x.msh.tmp-" + std::to_string(getpid()) + "-0";
    std::ofstream(dir / live) << "a concurrent run's file\n";

    const auto r = run_command(cli() + " mesh " + q(pipe()) + " --quiet -o " + q(dir / "x.msh") + " -o " +
                               q(dir / "y.vtu"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(temporaries_in(dir.path()), std::vector<std::string>{live});
}

// An interrupt while a .vtm's parts are written leaves no folder for them.
TEST_F(CliMeshSafety, SigtermWhileWritingAVtmLeavesNoFolder) {
    const auto run = tubemesh::testing::signal_when_created(
        {TUBEMESH_CLI, "mesh", "--quiet", "-o", (dir / "w.vtm").string(), "-o", (dir / "x.msh").string()}, dir.path(),
        "w", SIGTERM);
    ASSERT_TRUE(run.sent);
    EXPECT_TRUE(WIFSIGNALED(run.status) && WTERMSIG(run.status) == SIGTERM) << "status " << run.status;
    EXPECT_TRUE(names_in(dir.path()).empty()) << names_in(dir.path()).front();
}

// The files a .vtm lists (file="..." attributes), sorted.
std::vector<std::string> listed_parts(const fs::path& vtm) {
    const std::string text = read_file(vtm);
    std::vector<std::string> files;
    for (std::size_t at = text.find("file=\""); at != std::string::npos; at = text.find("file=\"", at)) {
        at += 6;
        files.push_back(text.substr(at, text.find('"', at) - at));
    }
    std::sort(files.begin(), files.end());
    return files;
}

// A second model meshed into the same .vtm: its folder then holds the new model's parts only
// (the first one's extra pipes are gone), and a file of the user's that is no part stays.
TEST_F(CliMeshSafety, AVtmFolderHoldsOnlyThisRunsParts) {
    const fs::path three = tubemesh::testing::built_preset(dir.path(), "three-pipes");
    const fs::path out = dir / "out";
    fs::create_directory(out);
    const auto first = run_command(cli() + " mesh " + q(three) + " --quiet -o " + q(out / "x.vtm"));
    ASSERT_EQ(first.exit_code, 0) << first.err;
    ASSERT_TRUE(fs::exists(out / "x" / "boundary_pipe_3.vtu"));
    std::ofstream(out / "x" / "notes.txt") << "the user's\n";

    const auto second = run_command(cli() + " mesh " + q(pipe()) + " --quiet -o " + q(out / "x.vtm"));
    ASSERT_EQ(second.exit_code, 0) << second.err;
    std::vector<std::string> expected;
    for (const std::string& f : listed_parts(out / "x.vtm")) expected.push_back(fs::path(f).filename().string());
    expected.push_back("notes.txt");
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(names_in(out / "x"), expected);
    EXPECT_FALSE(fs::exists(out / "x" / "boundary_pipe_2.vtu"));
}

// --max-elements caps what is written: the crankshaft at --size 25 passes the estimate for
// 8000 elements (6.5e3) and would make about 1.6e4; the run stops at a stage's end with the
// counts so far, exit 2, and no file.
TEST_F(CliMeshSafety, MaxElementsCapsTheRealCounts) {
    const fs::path in = tubemesh::testing::built_preset(dir.path(), "paper-ex3");
    const auto r = run_command(cli() + " mesh " + q(in) + " --size 25 --max-elements 8000 --quiet -o " +
                               q(dir / "out.msh"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("stage the mesh has "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("more than --max-elements 8e+03"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.msh"));
}

TEST_F(CliMeshSafety, SigtermWhileWritingLeavesNothing) { interrupt_while_writing(dir.path(), SIGTERM); }
TEST_F(CliMeshSafety, SigintWhileWritingLeavesNothing) { interrupt_while_writing(dir.path(), SIGINT); }
TEST_F(CliMeshSafety, SighupWhileWritingLeavesNothing) { interrupt_while_writing(dir.path(), SIGHUP); }

}  // namespace
