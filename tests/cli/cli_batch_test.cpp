// `tubemesh make-dam` and `tubemesh batch` end to end on a small dam (2 x 2 blocks of about
// 14,000 elements): every block meshed, checked and reopened by Gmsh; the same bytes for any
// thread count, after kill -9 at five moments and a resume, as shards merged; changed blocks
// redone and unchanged ones kept; a corrupt, crashing or hanging block failing alone.
// Faults come from TUBEMESH_BATCH_TEST_FAULT (batch/test_hooks.hpp): no test sleeps.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "batch/status.hpp"
#include "tests/cli/batch_runs.hpp"
#include "tests/support/outside_readers.hpp"

namespace tubemesh::testing {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// A block without pyramids or hexes (an all-tet block, a failed or pending one) has blank
// measures for those kinds: a 0 would read as a flat cell.
TEST(BatchStatusCsv, KindsWithoutCellsHaveBlankMeasures) {
    batch::BlockRecord tets_only{.id = "plain", .status = "done", .nodes = 40, .tets = 100};
    tets_only.tet_collapse = {0.25, 0.75};
    batch::BlockRecord pending{.id = "later"};
    std::istringstream csv(batch::status_csv({tets_only, pending}));
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(csv, line);) {
        rows.emplace_back();
        std::istringstream fields(line);
        for (std::string f; std::getline(fields, f, ',');) rows.back().push_back(f);
        if (!line.empty() && line.back() == ',') rows.back().emplace_back();
    }
    ASSERT_EQ(rows.size(), 3u);
    std::map<std::string, std::string> plain, later;
    for (std::size_t c = 0; c < rows[0].size(); ++c) {
        plain[rows[0][c]] = c < rows[1].size() ? rows[1][c] : "";
        later[rows[0][c]] = c < rows[2].size() ? rows[2][c] : "";
    }
    EXPECT_EQ(plain["tets"], "100");
    EXPECT_EQ(plain["pyramids"], "0");
    EXPECT_EQ(plain["tet_collapse_min"], "0.25");
    EXPECT_EQ(plain["tet_collapse_mean"], "0.75");
    for (const char* blank : {"pyramid_scaled_jacobian_min", "pyramid_scaled_jacobian_mean", "hex_scaled_jacobian_min",
                              "hex_scaled_jacobian_mean", "hex_condition_max"}) {
        EXPECT_EQ(plain.count(blank), 1u) << blank;
        EXPECT_EQ(plain[blank], "") << blank;
        EXPECT_EQ(later[blank], "") << blank;
    }
    EXPECT_EQ(later["tet_collapse_min"], "");
}

TEST(CliMakeDam, SameSeedSameDamAndEveryBlockHasItsRole) {
    TempDir tmp;
    const std::string args = " --columns 3 --lifts 2 --specs " + kSmallDam;
    ASSERT_EQ(run_command(cli() + " make-dam --seed 7 -o " + q(tmp / "a") + args).exit_code, 0);
    ASSERT_EQ(run_command(cli() + " make-dam --seed 7 -o " + q(tmp / "b") + args).exit_code, 0);
    ASSERT_EQ(run_command(cli() + " make-dam --seed 8 -o " + q(tmp / "c") + args).exit_code, 0);
    EXPECT_EQ(read_text(tmp / "a" / "manifest.json"), read_text(tmp / "b" / "manifest.json"));
    EXPECT_EQ(read_text(tmp / "a" / "c2-l1.json"), read_text(tmp / "b" / "c2-l1.json"));
    EXPECT_NE(read_text(tmp / "a" / "c2-l1.json"), read_text(tmp / "c" / "c2-l1.json"));

    const json m = json::parse(read_text(tmp / "a" / "manifest.json"));
    ASSERT_EQ(m["blocks"].size(), 6u);
    std::map<std::string, std::string> roles;
    for (const json& b : m["blocks"]) roles[b["id"]] = b["info"]["role"];
    EXPECT_EQ(roles["c1-l1"], "foundation");
    EXPECT_EQ(roles["c3-l2"], "crest");
    EXPECT_EQ(roles["c2-l1"], "lift");
    // Lifts stack: the second lift starts where the first ends.
    const json& l1 = m["blocks"][0]["info"];
    const json& l2 = m["blocks"][1]["info"];
    EXPECT_DOUBLE_EQ(l2["origin"][2].get<double>(), l1["origin"][2].get<double>() + l1["size"][2].get<double>());
}

// Cooling pipes laid on the lift joint: every serpentine's centre line at the height asked for,
// in pipe radii above its lift's bottom; a height that would cut the bottom is refused.
TEST(CliMakeDam, PipeHeightPutsEverySerpentineThatManyRadiiAboveItsLiftsBottom) {
    TempDir tmp;
    const auto r = run_command(cli() + " make-dam --columns 2 --lifts 2 --pipe-height 1.5 --specs -o " +
                               q(tmp / "d") + " " + kSmallDam);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    int pipes = 0;
    for (const char* id : {"c1-l2", "c2-l1"}) {
        const json spec = json::parse(read_text(tmp / "d" / (std::string(id) + ".json")));
        ASSERT_EQ(spec["pipes"].size(), 1u) << id;
        const json& pipe = spec["pipes"][0];
        const double radius = pipe["diameter"].get<double>() / 2;
        for (const json& point : pipe["points"]) {
            EXPECT_NEAR(point[2].get<double>(), 1.5 * radius, 1e-12 * radius) << id;
            ++pipes;
        }
    }
    EXPECT_GT(pipes, 4);
    const auto low = run_command(cli() + " make-dam --columns 2 --lifts 2 --pipe-height 0.9 --specs -o " +
                                 q(tmp / "e") + " " + kSmallDam);
    EXPECT_EQ(low.exit_code, 2);
    EXPECT_NE(low.err.find("--pipe-height"), std::string::npos) << low.err;
    EXPECT_FALSE(fs::exists(tmp / "e"));
}

// `make-dam ... -o DIR` as an argument list, for signal_when_created.
std::vector<std::string> make_dam_args(const fs::path& dir) {
    std::vector<std::string> args = {TUBEMESH_CLI, "make-dam", "--columns", "2", "--lifts", "2"};
    std::istringstream ranges(kSmallDam);
    for (std::string word; ranges >> word;) args.push_back(word);
    args.insert(args.end(), {"-o", dir.string()});
    return args;
}

// A disk that fills after the first blocks (a file-size limit between the pipeless blocks' STEP
// files and those with a pipe): the system's reason, and no folder at all.
TEST(CliMakeDam, AFullDiskGivesTheRealReasonAndLeavesNoFolder) {
    TempDir tmp;
    const ProcessResult r = run_command("prlimit --fsize=60000 " + cli() + " make-dam --columns 2 --lifts 2 " +
                                        kSmallDam + " -o " + q(tmp / "dam"));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(fs::is_empty(tmp.path()));
}

// SIGTERM once the first block's file is complete: nothing is left, not even the folder.
TEST(CliMakeDam, SigtermLeavesNoFolder) {
    TempDir tmp;
    const SignalledRun run = signal_when_created(make_dam_args(tmp / "dam"), tmp.path(), "c1-l1.step", SIGTERM);
    ASSERT_TRUE(run.sent);
    EXPECT_TRUE(WIFSIGNALED(run.status) && WTERMSIG(run.status) == SIGTERM) << "status " << run.status;
    EXPECT_TRUE(fs::is_empty(tmp.path()));
}

// A folder that already holds files is refused before any block is built; an empty one is filled.
TEST(CliMakeDam, WritesANewOrEmptyFolderOnly) {
    TempDir tmp;
    fs::create_directory(tmp / "full");
    std::ofstream(tmp / "full" / "mine.txt") << "the user's\n";
    const ProcessResult full = run_command(cli() + " make-dam --specs -o " + q(tmp / "full"));
    EXPECT_EQ(full.exit_code, 2);
    EXPECT_NE(full.err.find("it already holds files"), std::string::npos) << full.err;
    EXPECT_EQ(read_text(tmp / "full" / "mine.txt"), "the user's\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(tmp / "full"), fs::directory_iterator()), 1);

    fs::create_directory(tmp / "empty");
    EXPECT_EQ(run_command(cli() + " make-dam --specs --quiet -o " + q(tmp / "empty")).exit_code, 0);
    EXPECT_TRUE(fs::exists(tmp / "empty" / "manifest.json"));
    EXPECT_EQ(run_command(cli() + " make-dam --specs --quiet -o " + q(tmp / "new" / "dam")).exit_code, 0);
    EXPECT_TRUE(fs::exists(tmp / "new" / "dam" / "manifest.json"));
    EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 3);  // no temporaries
}

TEST(CliBatch, MeshesEveryBlockAndEveryMeshPassesTheCheckAndOpensInGmsh) {
    const SmallDam dam;
    const ProcessResult r = run_command(cli() + " batch " + q(dam.manifest()) + " -o " + q(dam.dir / "out"));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const std::vector<Row> rows = catalogue_rows(dam.dir / "out");
    ASSERT_EQ(rows.size(), 4u);
    for (const Row& row : rows) {
        EXPECT_EQ(row.at("status"), "done") << row.at("error");
        const fs::path msh = dam.dir / "out" / (row.at("id") + ".msh");
        const ProcessResult check = run_command(cli() + " check --json " + q(msh));
        ASSERT_EQ(check.exit_code, 0) << check.out;
        const json c = json::parse(check.out);
        EXPECT_EQ(std::to_string(c["tets"].get<long>()), row.at("tets"));
        EXPECT_EQ(std::to_string(c["hexes"].get<long>()), row.at("hexes"));
        const json seen = run_script("gmsh_summary.py", {msh.string()});
        EXPECT_EQ(seen["elements"].value("4", 0), std::stol(row.at("tets")));
        EXPECT_EQ(seen["elements"].value("5", 0), std::stol(row.at("hexes")));
        EXPECT_EQ(seen["elements"].value("7", 0), std::stol(row.at("pyramids")));
        // The report says the same, and the output's hash is the file's.
        const json report = json::parse(read_text(dam.dir / "out" / row.at("report")));
        EXPECT_EQ(std::to_string(report["tets"].get<long>()), row.at("tets"));
        EXPECT_EQ(row.at("outputs"), row.at("id") + ".msh=" + sha256_of(msh));
    }
    // Two foundation/crest blocks without pipes, two lifts with one.
    EXPECT_EQ(rows[0].at("hexes"), "0");
    EXPECT_NE(rows[1].at("hexes"), "0");

    const ProcessResult status = run_command(cli() + " batch --status " + q(dam.dir / "out"));
    EXPECT_EQ(status.exit_code, 0);
    EXPECT_NE(status.out.find("4 blocks: 4 done, 0 failed, 0 pending"), std::string::npos) << status.out;
    EXPECT_NE(status.out.find("worst tet collapse"), std::string::npos);
}

TEST(CliBatch, OneOrTwoThreadsWriteTheSameBytes) {
    const SmallDam dam;
    EXPECT_EQ(batch(dam, "one", "--threads 1").exit_code, 0);
    EXPECT_EQ(batch(dam, "two", "--threads 2").exit_code, 0);
    EXPECT_EQ(stable(catalogue_rows(dam.dir / "one")), stable(catalogue_rows(dam.dir / "two")));
    for (const Row& row : catalogue_rows(dam.dir / "one")) {
        const std::string msh = row.at("id") + ".msh";
        EXPECT_EQ(sha256_of(dam.dir / "one" / msh), sha256_of(dam.dir / "two" / msh));
    }
}

// Kill -9 of the batch at five moments: with the plan written and no block started; in a
// worker before it meshes; after a worker wrote its files and before the catalogue knows;
// inside a block's catalogue transaction; after a block's row committed. The same command
// then finishes the run, and its files and catalogue equal an uninterrupted run's.
TEST(CliBatch, KillNineAtFiveMomentsThenResumeEqualsAnUninterruptedRun) {
    const SmallDam dam;
    ASSERT_EQ(batch(dam, "reference", "--threads 2").exit_code, 0);
    const std::vector<Row> reference = stable(catalogue_rows(dam.dir / "reference"));

    for (const std::string fault : {"plan:1", "start:c2-l1", "written:c1-l2", "commit:2", "recorded:3"}) {
        SCOPED_TRACE(fault);
        const std::string out = "killed-" + fault.substr(0, fault.find(':'));
        const ProcessResult killed = batch(dam, out, "--threads 2", "TUBEMESH_BATCH_TEST_FAULT=" + fault);
        EXPECT_TRUE(killed.exit_code == 137 || killed.exit_code == -1) << killed.exit_code << killed.err;
        // Whatever is under a final name is complete: every .msh there passes the check.
        for (const fs::directory_entry& e : fs::directory_iterator(dam.dir / out))
            if (e.path().extension() == ".msh") {
                EXPECT_EQ(run_command(cli() + " check " + q(e.path())).exit_code, 0) << e.path();
            }

        const ProcessResult resumed = batch(dam, out, "--threads 2");
        ASSERT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
        EXPECT_EQ(stable(catalogue_rows(dam.dir / out)), reference);
        for (const Row& row : reference)
            EXPECT_EQ(sha256_of(dam.dir / out / (row.at("id") + ".msh")),
                      sha256_of(dam.dir / "reference" / (row.at("id") + ".msh")));
        for (const fs::directory_entry& e : fs::directory_iterator(dam.dir / out))
            EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
    }
}

TEST(CliBatch, AChangedBlockIsRedoneAndUnchangedOnesAreNot) {
    const SmallDam dam;
    ASSERT_EQ(batch(dam, "out", "").exit_code, 0);
    const std::vector<Row> before = catalogue_rows(dam.dir / "out");

    // c1-l2 gets other options, c2-l1's mesh file is removed; the others stay as they are.
    json m = json::parse(read_text(dam.manifest()));
    for (json& b : m["blocks"])
        if (b["id"] == "c1-l2") b["options"] = {{"gradation", 1.4}};
    std::ofstream(dam.manifest()) << m.dump(2);
    fs::remove(dam.dir / "out" / "c2-l1.msh");

    const ProcessResult again = batch(dam, "out", "--verbose");
    ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
    EXPECT_NE(again.out.find("2 done before, 2 meshed now"), std::string::npos) << again.out;
    const std::vector<Row> after = catalogue_rows(dam.dir / "out");
    for (std::size_t i = 0; i < after.size(); ++i) {
        const std::string& id = after[i].at("id");
        const bool redone = id == "c1-l2" || id == "c2-l1";
        EXPECT_EQ(after[i].at("worker") != before[i].at("worker"), redone) << id;
        EXPECT_EQ(again.out.find(id + " done:") != std::string::npos, redone) << id;
        EXPECT_EQ(after[i].at("options_sha256") != before[i].at("options_sha256"), id == "c1-l2") << id;
    }
    EXPECT_TRUE(fs::exists(dam.dir / "out" / "c2-l1.msh"));
}

// A done block's mesh altered in place at the same size: --status no longer counts it as done,
// and the next run redoes it (the catalogue holds the SHA-256 of what the worker wrote).
TEST(CliBatch, AnOutputAlteredAtItsSizeIsRedone) {
    const SmallDam dam;
    ASSERT_EQ(batch(dam, "out", "").exit_code, 0);
    const fs::path msh = dam.dir / "out" / "c2-l1.msh";
    const std::string written = sha256_of(msh);
    const auto size = fs::file_size(msh);
    {
        std::fstream f(msh, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(static_cast<std::streamoff>(size / 2));
        const char c = static_cast<char>(f.get());
        f.seekp(static_cast<std::streamoff>(size / 2));
        f.put(static_cast<char>(~c));
    }
    ASSERT_EQ(fs::file_size(msh), size);
    ASSERT_NE(sha256_of(msh), written);

    const ProcessResult status = run_command(cli() + " batch --status " + q(dam.dir / "out"));
    EXPECT_EQ(status.exit_code, 1);
    EXPECT_NE(status.out.find("4 blocks: 3 done, 0 failed, 1 pending"), std::string::npos) << status.out;
    EXPECT_NE(status.out.find("to redo c2-l1: c2-l1.msh changed since it was written"), std::string::npos)
        << status.out;

    const ProcessResult again = batch(dam, "out", "");
    ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
    EXPECT_NE(again.out.find("3 done before, 1 meshed now"), std::string::npos) << again.out;
    EXPECT_EQ(sha256_of(msh), written);
}

TEST(CliBatch, ACorruptBlockFailsAloneWithItsErrorAndExitOne) {
    const SmallDam dam;
    std::ofstream(dam.dir / "c2-l1.step") << "ISO-10303-21;\nthis is not a STEP file\n";
    const ProcessResult r = batch(dam, "out", "");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.err.find("block c2-l1 failed"), std::string::npos) << r.err;
    for (const Row& row : catalogue_rows(dam.dir / "out")) {
        EXPECT_EQ(row.at("status"), row.at("id") == "c2-l1" ? "failed" : "done") << row.at("id");
        if (row.at("id") == "c2-l1") {
            EXPECT_NE(row.at("error").find("c2-l1.step"), std::string::npos) << row.at("error");
            EXPECT_EQ(row.at("error").find('\n'), std::string::npos);
            EXPECT_FALSE(fs::exists(dam.dir / "out" / "c2-l1.msh"));
        }
    }
    const ProcessResult status = run_command(cli() + " batch --status " + q(dam.dir / "out"));
    EXPECT_EQ(status.exit_code, 1);
    EXPECT_NE(status.out.find("3 done, 1 failed"), std::string::npos) << status.out;
}

TEST(CliBatch, ADeviceNamedAsABlockInputFailsThatBlockAndHangsNothing) {
    const SmallDam dam;
    json m = json::parse(read_text(dam.manifest()));
    m["blocks"][0]["cad"] = "/dev/zero";
    m["blocks"][1].erase("cad");
    m["blocks"][1]["spec"] = "/dev/zero";
    std::ofstream(dam.manifest()) << m.dump(2);
    const ProcessResult r = batch(dam, "out", "");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    for (const Row& row : catalogue_rows(dam.dir / "out")) {
        const bool bad = row.at("id") == m["blocks"][0]["id"] || row.at("id") == m["blocks"][1]["id"];
        EXPECT_EQ(row.at("status"), bad ? "failed" : "done") << row.at("id");
        if (bad) {
            EXPECT_NE(row.at("error").find("not a regular file"), std::string::npos) << row.at("error");
        }
    }
}

TEST(CliBatch, ACrashingOrHangingWorkerCostsOnlyItsBlock) {
    const SmallDam dam;
    const ProcessResult crash = batch(dam, "crash", "--threads 2", "TUBEMESH_BATCH_TEST_FAULT=crash:c1-l2");
    EXPECT_EQ(crash.exit_code, 1) << crash.out << crash.err;
    // The hanging block alone gets a short limit: the others must not race a clock.
    const std::string manifest = read_text(dam.manifest());
    json m = json::parse(manifest);
    for (json& b : m["blocks"])
        if (b["id"] == "c2-l2") b["options"] = {{"time_limit", 1}};
    std::ofstream(dam.manifest()) << m.dump(2);
    const ProcessResult hang = batch(dam, "hang", "--threads 2", "TUBEMESH_BATCH_TEST_FAULT=hang:c2-l2");
    std::ofstream(dam.manifest()) << manifest;
    EXPECT_EQ(hang.exit_code, 1) << hang.out << hang.err;
    for (const auto& [out, bad, why] : {std::tuple{"crash", "c1-l2", "signal 11"}, {"hang", "c2-l2", "time limit"}})
        for (const Row& row : catalogue_rows(dam.dir / out)) {
            SCOPED_TRACE(std::string(out) + " " + row.at("id"));
            EXPECT_EQ(row.at("status"), row.at("id") == bad ? "failed" : "done");
            if (row.at("id") == bad) {
                EXPECT_NE(row.at("error").find(why), std::string::npos) << row.at("error");
            }
        }

    // A worker that dies once is dealt its block again, which then ends as if nothing happened.
    ASSERT_EQ(batch(dam, "reference", "--threads 2").exit_code, 0);
    const ProcessResult once = batch(dam, "once", "--threads 2 --verbose", "TUBEMESH_BATCH_TEST_FAULT=die-once:c2-l1");
    EXPECT_EQ(once.exit_code, 0) << once.out << once.err;
    EXPECT_NE(once.out.find("c2-l1: its worker died, dealt again"), std::string::npos) << once.out;
    EXPECT_EQ(stable(catalogue_rows(dam.dir / "once")), stable(catalogue_rows(dam.dir / "reference")));
}

TEST(CliBatch, ShardsMergedEqualTheSingleRun) {
    const SmallDam dam;
    ASSERT_EQ(batch(dam, "single", "").exit_code, 0);
    EXPECT_EQ(batch(dam, "sharded", "--shard 0/2").exit_code, 0);
    EXPECT_EQ(batch(dam, "sharded", "--shard 1/2").exit_code, 0);
    EXPECT_TRUE(fs::exists(dam.dir / "sharded" / "catalogue.shard-0-of-2.sqlite"));
    const ProcessResult merged = run_command(cli() + " batch --merge " + q(dam.dir / "sharded"));
    ASSERT_EQ(merged.exit_code, 0) << merged.out << merged.err;
    EXPECT_EQ(stable(catalogue_rows(dam.dir / "sharded")), stable(catalogue_rows(dam.dir / "single")));
}

TEST(CliBatch, AWrongManifestOrCommandLineExitsTwoWithOneLine) {
    const SmallDam dam;
    const json good = json::parse(read_text(dam.manifest()));
    auto with = [&](const std::function<void(json&)>& edit) {
        json m = good;
        edit(m);
        const fs::path p = dam.dir / "edited.json";
        std::ofstream(p) << m.dump(2);
        return run_command(cli() + " batch " + q(p) + " -o " + q(dam.dir / "out"));
    };
    const fs::path huge = dam.dir / "huge.json";
    std::ofstream(huge) << R"({"tubemesh_batch": 1e99999, "blocks": []})";
    const std::vector<std::pair<ProcessResult, std::string>> cases = {
        {with([](json& m) { m["blocks"][1]["id"] = "c1-l1"; }), "appears twice"},
        {run_command(cli() + " batch " + q(huge) + " -o " + q(dam.dir / "out")), "is not valid JSON"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"gradation", 9}}; }), "gradation must be between"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"circ", 1e32}}; }), "\"circ\" must be a whole number"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"sise", 1}}; }), "unknown option \"sise\""},
        {with([](json& m) { m["blocks"][0]["options"] = {{"layers", nullptr}}; }), "\"layers\" must be a number, got null"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"chordal", 0}}; }), "chordal must be between"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"move_apexes", 1}}; }), "\"move_apexes\" must be true or false"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"slide_surface", "yes"}}; }),
         "\"slide_surface\" must be true or false"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"pipe_network", true}, {"formats", {"msh"}}}; }),
         "pipe_network writes the water into a .inp"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"reverse_flow", {"a"}}}; }),
         "\"reverse_flow\" takes whole numbers"},
        {with([](json& m) { m["blocks"][0]["options"] = {{"local_ring", 0}}; }), "\"local_ring\" must be true or false"},
        {with([](json& m) { m["blocks"][0]["id"] = "../x"; }), "letters, digits"},
        {with([](json& m) { m.erase("tubemesh_batch"); }), "not a tubemesh batch manifest"},
        {with([](json& m) { m["name"] = {{"size", 1}}; }), "\"name\" must be a string"},
        {run_command(cli() + " batch " + q(dam.manifest()) + " -o " + q(dam.dir / "o") + " --shard 2/2"), "--shard"},
        {run_command(cli() + " batch " + q(dam.dir / "missing.json") + " -o " + q(dam.dir / "o")), "missing.json"},
    };
    for (const auto& [r, words] : cases) {
        EXPECT_EQ(r.exit_code, 2) << words << ": " << r.err;
        EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dam.dir / "out" / "catalogue.sqlite"));
}

}  // namespace
}  // namespace tubemesh::testing
