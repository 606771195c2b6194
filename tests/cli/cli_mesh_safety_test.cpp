// Nothing lost: an interrupted or failing `tubemesh mesh` leaves no temporary file behind and
// every file that existed before it intact; options are refused at parse time in plain numbers.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/inotify.h>
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

    const int watch = inotify_init1(IN_CLOEXEC);
    ASSERT_GE(watch, 0);
    ASSERT_GE(inotify_add_watch(watch, dir.c_str(), IN_CREATE), 0);
    const std::string x = (dir / "x.msh").string(), y = (dir / "y.vtu").string(), z = (dir / "z.inp").string();
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // The dam block (no input): big enough that writing three files takes a while.
        execl(TUBEMESH_CLI, TUBEMESH_CLI, "mesh", "--quiet", "-o", x.c_str(), "-o", y.c_str(), "-o", z.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    bool sent = false;
    alignas(inotify_event) char buffer[4096];
    while (!sent) {
        const ssize_t n = read(watch, buffer, sizeof buffer);
        if (n <= 0) break;
        for (char* p = buffer; p < buffer + n && !sent;) {
            const auto* e = reinterpret_cast<const inotify_event*>(p);
            if (e->len > 0 && std::string(e->name).rfind(".x.msh.tmp-", 0) == 0) sent = kill(child, signal_number) == 0;
            p += sizeof(inotify_event) + e->len;
        }
    }
    close(watch);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(sent);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "status " << status;
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

TEST_F(CliMeshSafety, SigtermWhileWritingLeavesNothing) { interrupt_while_writing(dir.path(), SIGTERM); }
TEST_F(CliMeshSafety, SigintWhileWritingLeavesNothing) { interrupt_while_writing(dir.path(), SIGINT); }
TEST_F(CliMeshSafety, SighupWhileWritingLeavesNothing) { interrupt_while_writing(dir.path(), SIGHUP); }

}  // namespace
