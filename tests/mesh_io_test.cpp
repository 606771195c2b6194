// Mesh files: exact MSH round trips, reading Gmsh-style input, errors, atomic writes, and
// the Abaqus face mapping. Outside readers (Gmsh, meshio) are in mesh_io_readers_test.cpp,
// the corruption fuzzing in mesh_io_fuzz_test.cpp.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/io/abaqus_faces.hpp"
#include "engine/io/abaqus_names.hpp"
#include "engine/io/abaqus_number.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/boundary_cell_faces.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/io/msh_reader.hpp"
#include "tests/support/mesh_io_samples.hpp"
#include "tests/support/process.hpp"
#include "tests/support/sample_meshes.hpp"
#include "tests/support/error_of.hpp"

namespace tubemesh {
namespace {

using testing::error_of;
using testing::TempDir;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

HybridMesh round_trip(const HybridMesh& mesh, MshEncoding encoding) {
    TempDir dir;
    const auto path = dir / "mesh.msh";
    write_msh(mesh, path, encoding);
    return read_msh(path);
}

// ---------------------------------------------------------------- MSH round trips

class MshRoundTrip : public ::testing::TestWithParam<MshEncoding> {};

TEST_P(MshRoundTrip, ConformingPatchIsIdentical) {
    const HybridMesh mesh = testing::conforming_patch();
    EXPECT_EQ(testing::first_difference(round_trip(mesh, GetParam()), mesh), "");
}

TEST_P(MshRoundTrip, MixedGridIsIdentical) {
    const HybridMesh mesh = testing::mixed_grid(6);
    ASSERT_GT(mesh.cell_count(CellKind::Hex), 0u);
    ASSERT_GT(mesh.cell_count(CellKind::Pyramid), 0u);
    ASSERT_GT(mesh.cell_count(CellKind::Tet), 0u);
    ASSERT_GT(mesh.face_count(FaceKind::Tri), 0u);
    ASSERT_GT(mesh.face_count(FaceKind::Quad), 0u);
    const HybridMesh back = round_trip(mesh, GetParam());
    EXPECT_EQ(back.x, mesh.x);  // bit-exact coordinates, also through ASCII text
    EXPECT_EQ(back.region_names, mesh.region_names);
    EXPECT_EQ(back.surface_group_names, mesh.surface_group_names);
    EXPECT_EQ(testing::first_difference(back, mesh), "");
}

TEST_P(MshRoundTrip, PointsWithoutCellsOrGroups) {
    HybridMesh mesh;
    mesh.add_point(1, 2, 3);
    mesh.add_point(-0.1, 1e-300, 4e300);
    EXPECT_EQ(testing::first_difference(round_trip(mesh, GetParam()), mesh), "");
    EXPECT_EQ(testing::first_difference(round_trip(HybridMesh{}, GetParam()), HybridMesh{}), "");
}

TEST_P(MshRoundTrip, NamesWithSpacesAndUtf8) {
    HybridMesh mesh = testing::conforming_patch();
    mesh.region_names[0] = "hex ring (swept), Ø 0.04";
    mesh.surface_group_names[1] = "";
    EXPECT_EQ(testing::first_difference(round_trip(mesh, GetParam()), mesh), "");
}

INSTANTIATE_TEST_SUITE_P(Encodings, MshRoundTrip, ::testing::Values(MshEncoding::Ascii, MshEncoding::Binary),
                         [](const auto& info) { return info.param == MshEncoding::Ascii ? "Ascii" : "Binary"; });

TEST(MshWriter, AsciiHeaderAndBinaryHeader) {
    TempDir dir;
    const HybridMesh mesh = testing::conforming_patch();
    write_msh(mesh, dir / "a.msh", MshEncoding::Ascii);
    write_msh(mesh, dir / "b.msh", MshEncoding::Binary);
    const std::string a = testing::read_text(dir / "a.msh");
    const std::string b = testing::read_text(dir / "b.msh");
    EXPECT_EQ(a.rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Comments\nlength unit: not known", 0), 0u) << a;
    EXPECT_TRUE(contains(a, "$EndComments\n$PhysicalNames\n5\n2 1 \"hex_sides\"\n"));
    EXPECT_EQ(b.rfind(std::string("$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n$Comments\n", 50), 0), 0u);
    EXPECT_TRUE(contains(a, "3 3 \"tets\"\n"));
}

TEST(MshWriter, NameGmshCannotHoldIsAnErrorAndLeavesNoFile) {
    TempDir dir;
    HybridMesh mesh = testing::conforming_patch();
    mesh.region_names[1] = "say \"pyramids\"";
    const std::string message = error_of([&] { write_msh(mesh, dir / "m.msh"); });
    EXPECT_TRUE(contains(message, "double quote")) << message;
    EXPECT_TRUE(contains(message, "m.msh")) << message;
    EXPECT_EQ(testing::entry_count(dir.path()), 0);
}

TEST(MshWriter, InvalidLayoutIsAnError) {
    TempDir dir;
    HybridMesh mesh = testing::conforming_patch();
    mesh.block(CellKind::Tet).nodes[0] = 99;
    EXPECT_TRUE(contains(error_of([&] { write_msh(mesh, dir / "m.msh"); }), "refers to node 99"));
    EXPECT_EQ(testing::entry_count(dir.path()), 0);
}

// ---------------------------------------------------------------- reading Gmsh-style files

// What Gmsh writes and tubemesh does not: nodes over several entity blocks, parametric
// coordinates, sparse unsorted tags, entities without physical groups, unnamed physical
// groups, extra sections.
constexpr const char* kGmshStyle = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
3 7 "solid"
$EndPhysicalNames
$Entities
1 1 1 2
5 0 0 0 0
3 0 0 0 1 0 0 0 2 5 -5
8 0 0 0 1 1 0 1 12 1 3
1 0 0 0 1 1 1 1 7 0
2 0 0 0 1 1 1 0 0
$EndEntities
$Nodes
3 5 10 50
0 5 0 1
50
0 0 1
2 8 1 2
30
10
1 0 0 0.5 0.5
0 1 0 0.25 0.75
3 1 0 2
20
40
0 0 0
1 1 1
$EndNodes
$Elements
3 4 1 100
3 1 4 1
100 20 30 10 50
3 2 4 1
7 40 30 10 50
2 8 2 2
9 20 30 10
8 20 10 50
$EndElements
$NodeData
1
"temperature"
$EndNodeData
)";

TEST(MshReader, ReadsGmshStyleFile) {
    TempDir dir;
    testing::write_text(dir / "g.msh", kGmshStyle);
    const HybridMesh m = read_msh(dir / "g.msh");
    // Points by ascending tag: 10, 20, 30, 40, 50.
    EXPECT_EQ(m.x, (std::vector<double>{0, 0, 1, 1, 0}));
    EXPECT_EQ(m.y, (std::vector<double>{1, 0, 0, 1, 0}));
    EXPECT_EQ(m.z, (std::vector<double>{0, 0, 0, 1, 1}));
    // Tets by ascending tag: 7 (volume entity 2, no physical), then 100 (physical 7).
    EXPECT_EQ(m.block(CellKind::Tet).nodes, (std::vector<index_t>{3, 2, 0, 4, 1, 2, 0, 4}));
    EXPECT_EQ(m.region_names, (std::vector<std::string>{"solid", "volume_entity_2"}));
    EXPECT_EQ(m.block(CellKind::Tet).region, (std::vector<index_t>{1, 0}));
    // Triangles 8 then 9, on surface entity 8 with unnamed physical 12.
    EXPECT_EQ(m.block(FaceKind::Tri).nodes, (std::vector<index_t>{1, 0, 4, 1, 2, 0}));
    EXPECT_EQ(m.surface_group_names, (std::vector<std::string>{"surface_12"}));
}

TEST(MshReader, UnsupportedElementTypeIsAClearError) {
    std::string text = kGmshStyle;
    text.replace(text.find("2 8 2 2\n"), 8, "1 8 1 2\n");
    const std::string message = error_of([&] { io::read_msh_bytes(text, "g.msh"); });
    EXPECT_TRUE(contains(message, "g.msh: line 38: element type 1 (2-node line) is not supported")) << message;
}

TEST(MshReader, ErrorsNameTheLine) {
    std::string text = kGmshStyle;
    text.replace(text.find("0 1 0 0.25 0.75"), 15, "0 1 0 0.25 x.75");
    const std::string message = error_of([&] { io::read_msh_bytes(text, "g.msh"); });
    EXPECT_TRUE(contains(message, "g.msh: line 25: expected a parametric coordinate")) << message;
}

TEST(MshReader, UnknownNodeTagIsAnError) {
    std::string text = kGmshStyle;
    text.replace(text.find("9 20 30 10"), 10, "9 20 31 10");
    const std::string message = error_of([&] { io::read_msh_bytes(text, "g.msh"); });
    EXPECT_TRUE(contains(message, "line 39: element 9 refers to node tag 31")) << message;
}

TEST(MshReader, CoordinateThatIsNotANumberIsAnError) {
    for (const char* bad : {"nan", "inf"}) {
        std::string text = kGmshStyle;
        text.replace(text.find("0 1 0 0.25 0.75"), 15, std::string("0 ") + bad + " 0 0.25 0.75");
        const std::string message = error_of([&] { io::read_msh_bytes(text, "g.msh"); });
        EXPECT_TRUE(contains(message, "node 10 has a coordinate that is not a finite number")) << message;
    }
}

TEST(MshReader, DuplicateElementTagIsAnError) {
    std::string text = kGmshStyle;
    text.replace(text.find("7 40 30"), 7, "100 40 30");
    EXPECT_TRUE(contains(error_of([&] { io::read_msh_bytes(text, "g.msh"); }), "element tag 100 appears twice"));
}

TEST(MshReader, OtherVersionsAreRejected) {
    const std::string message = error_of([] { io::read_msh_bytes("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", "old.msh"); });
    EXPECT_TRUE(contains(message, "old.msh: line 2: MSH version 2.2 is not supported")) << message;
    EXPECT_TRUE(contains(error_of([] { io::read_msh_bytes("", "e.msh"); }), "the file is empty"));
    EXPECT_TRUE(contains(error_of([] { io::read_msh_bytes("solid cube\n", "s.msh"); }), "not a Gmsh MSH file"));
}

TEST(MshReader, BinaryErrorsNameTheByteOffset) {
    TempDir dir;
    write_msh(testing::conforming_patch(), dir / "b.msh", MshEncoding::Binary);
    std::string bytes = testing::read_text(dir / "b.msh");
    const std::size_t nodes = bytes.find("$Nodes\n") + 7;
    bytes.resize(nodes + 20);  // inside the $Nodes header
    const std::string message = error_of([&] { io::read_msh_bytes(bytes, "b.msh"); });
    EXPECT_TRUE(contains(message, "b.msh: byte offset " + std::to_string(nodes + 16) + ": the file ends inside"))
        << message;
}

TEST(MshReader, MissingFileAndDirectoryAreErrors) {
    TempDir dir;
    const std::string missing = error_of([&] { read_msh(dir / "nothing.msh"); });
    EXPECT_TRUE(contains(missing, "nothing.msh")) << missing;
    EXPECT_TRUE(contains(missing, "No such file or directory")) << missing;
    EXPECT_TRUE(contains(error_of([&] { read_msh(dir.path()); }), "Is a directory"));
}

// ---------------------------------------------------------------- atomic writes

class AtomicWrite : public ::testing::TestWithParam<const char*> {};

TEST_P(AtomicWrite, UnwritableDirectoryGivesErrorAndNoFile) {
    TempDir dir;
    testing::write_text(dir / "plain_file", "x");
    const auto path = dir / "plain_file" / (std::string("mesh") + GetParam());
    const std::string message = error_of([&] { write_mesh(testing::conforming_patch(), path); });
    EXPECT_TRUE(contains(message, path.string())) << message;
    EXPECT_TRUE(contains(message, "Not a directory")) << message;
    EXPECT_EQ(testing::entry_count(dir.path()), 1);
}

TEST_P(AtomicWrite, FailedRenameRemovesTheTemporary) {
    TempDir dir;
    const auto path = dir / (std::string("mesh") + GetParam());
    std::filesystem::create_directories(path / "occupied");  // a non-empty directory cannot be replaced
    const std::string message = error_of([&] { write_mesh(testing::conforming_patch(), path); });
    EXPECT_TRUE(contains(message, "cannot replace '" + path.string() + "'")) << message;
    EXPECT_EQ(testing::entry_count(dir.path()), 1);
}

TEST_P(AtomicWrite, ReplacesAnExistingFile) {
    TempDir dir;
    const auto path = dir / (std::string("mesh") + GetParam());
    testing::write_text(path, "old");
    write_mesh(testing::conforming_patch(), path);
    EXPECT_GT(std::filesystem::file_size(path), 100u);
    EXPECT_EQ(testing::entry_count(dir.path()), 1);
}

// A group's files appear together: a failure in the second leaves the first target as it was.
TEST_P(AtomicWrite, GroupFailingAtItsSecondFileKeepsTheFirstTarget) {
    TempDir dir;
    const auto first = dir / (std::string("first") + GetParam());
    testing::write_text(first, "old");
    HybridMesh broken = testing::conforming_patch();
    broken.block(CellKind::Tet).nodes[0] = 99;
    const std::string message = error_of([&] {
        io::CommitGroup group;
        write_mesh(testing::conforming_patch(), first);
        EXPECT_EQ(testing::read_text(first), "old");  // complete, but not renamed yet
        write_mesh(broken, dir / (std::string("second") + GetParam()));
        group.commit();
    });
    EXPECT_TRUE(contains(message, "refers to node 99")) << message;
    EXPECT_EQ(testing::read_text(first), "old");
    EXPECT_EQ(testing::entry_count(dir.path()), 1);
}

TEST_P(AtomicWrite, GroupRenamesEveryFileAtCommit) {
    TempDir dir;
    const auto first = dir / (std::string("first") + GetParam()), second = dir / (std::string("second") + GetParam());
    testing::write_text(first, "old");
    io::CommitGroup group;
    write_mesh(testing::conforming_patch(), first);
    write_mesh(testing::conforming_patch(), second);
    EXPECT_FALSE(std::filesystem::exists(second));
    group.commit();
    EXPECT_EQ(testing::read_text(first), testing::read_text(second));
    EXPECT_EQ(testing::entry_count(dir.path()), 2);
}

INSTANTIATE_TEST_SUITE_P(Formats, AtomicWrite, ::testing::Values(".msh", ".vtu", ".inp"),
                         [](const auto& info) { return std::string(info.param + 1); });

// A pid no process has: a child that has ended and been waited for.
pid_t dead_pid() {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    return child;
}

// Writing a file removes the temporaries a killed writer of the same file left; those of a live
// process (this one) and names that only look alike stay.
TEST(AtomicTemporaries, ThoseOfDeadWritersOfTheTargetGo) {
    TempDir dir;
    const std::string dead = std::to_string(dead_pid()), live = std::to_string(getpid());
    const std::vector<std::string> gone = {".m.msh.tmp-" + dead + "-0", ".m.msh.tmp-" + dead + "-17"};
    const std::vector<std::string> kept = {
        ".m.msh.tmp-" + live + "-0",   // a live writer's
        ".n.msh.tmp-" + dead + "-0",   // another target's
        "m.msh.tmp-" + dead + "-0",    // not hidden
        ".m.msh.tmp-" + dead + "-",    // no counter
        ".m.msh.tmp-x" + dead + "-0",  // no pid
        ".m.msh.tmp-" + dead + "-0a",  // more after the counter
        ".m.ms"};
    for (const auto& names : {gone, kept})
        for (const std::string& n : names) testing::write_text(dir / n, "x");
    write_mesh(testing::conforming_patch(), dir / "m.msh");
    for (const std::string& n : gone) EXPECT_FALSE(std::filesystem::exists(dir / n)) << n;
    for (const std::string& n : kept) EXPECT_TRUE(std::filesystem::exists(dir / n)) << n;
}

// A folder written all at once: nothing under the target until commit(), nothing at all (not
// even the parent folders it made) when destroyed before; a folder holding files is refused.
TEST(AtomicFolder, AppearsWholeOrNotAtAll) {
    TempDir dir;
    const auto target = dir / "new" / "dam";
    {
        io::AtomicFolder folder(target);
        testing::write_text(folder.path() / "a.txt", "a");
        EXPECT_FALSE(std::filesystem::exists(target));
        EXPECT_EQ(folder.final_names("cannot write '" + (folder.path() / "a.txt").string() + "'"),
                  "cannot write '" + (target / "a.txt").string() + "'");
    }
    EXPECT_EQ(testing::entry_count(dir.path()), 0);
    {
        io::AtomicFolder folder(target);
        testing::write_text(folder.path() / "a.txt", "a");
        folder.commit();
    }
    EXPECT_EQ(testing::read_text(target / "a.txt"), "a");
    EXPECT_EQ(testing::entry_count(dir / "new"), 1);
    EXPECT_TRUE(contains(error_of([&] { io::AtomicFolder again(target); }), "it already holds files"));
    std::filesystem::create_directory(dir / "empty");
    io::AtomicFolder empty(dir / "empty");
    empty.commit();
    EXPECT_EQ(testing::entry_count(dir.path()), 2);
}

TEST(WriteMesh, UnknownExtensionIsAnError) {
    TempDir dir;
    const std::string message = error_of([&] { write_mesh(testing::conforming_patch(), dir / "mesh.stl"); });
    EXPECT_TRUE(contains(message, "unknown mesh format '.stl'")) << message;
    EXPECT_TRUE(contains(error_of([&] { write_mesh(testing::conforming_patch(), dir / "mesh"); }), "no extension"));
    EXPECT_EQ(testing::entry_count(dir.path()), 0);
}

TEST(WriteMesh, ExtensionIsCaseInsensitive) {
    TempDir dir;
    write_mesh(testing::conforming_patch(), dir / "MESH.MSH");
    EXPECT_EQ(testing::first_difference(read_msh(dir / "MESH.MSH"), testing::conforming_patch()), "");
}

// ---------------------------------------------------------------- VTU

TEST(VtuWriter, HeaderCountsAndLegend) {
    TempDir dir;
    write_vtu(testing::conforming_patch(), dir / "m.vtu");
    const std::string text = testing::read_text(dir / "m.vtu");
    EXPECT_TRUE(contains(text, "header_type=\"UInt64\"")) << text;
    // The 12 volume cells only: the boundary faces go to the .vtm's boundary blocks.
    EXPECT_TRUE(contains(text, "<Piece NumberOfPoints=\"13\" NumberOfCells=\"12\">"));
    EXPECT_TRUE(contains(text, "region 1: pyramids"));
    EXPECT_TRUE(contains(text, "surface group 1: upper_sides"));
    EXPECT_TRUE(contains(text, "length unit: not known"));
    for (const char* name : {"connectivity", "offsets", "types", "kind", "group", "quality", "scaled_jacobian",
                             "min_dihedral", "aspect_ratio", "condition"})
        EXPECT_TRUE(contains(text, std::string("Name=\"") + name + "\"")) << name;
    EXPECT_FALSE(contains(text, "Name=\"dim\""));
    // One UInt8 per cell type: 8-byte header + 12 bytes = 20 bytes = 28 base64 characters.
    // Tets (10) first, then the pyramid (14) and the hex (12).
    EXPECT_TRUE(contains(text, "Name=\"types\" format=\"binary\">\n          DAAAAAAAAAAKCgoKCgoKCgoKDgw=\n"));
    // Field data before the piece: upper_sides is surface group 1, of dimension 2.
    EXPECT_LT(text.find("<FieldData>"), text.find("<Piece "));
    EXPECT_TRUE(contains(text, "<DataArray type=\"Int32\" Name=\"upper_sides\" NumberOfTuples=\"2\" "
                               "format=\"binary\">\n          CAAAAAAAAAABAAAAAgAAAA==\n"));
}

// A .vtm that cannot be completed leaves nothing it made: its folder of blocks goes too.
TEST(VtmWriter, FailureLeavesNothingItMade) {
    TempDir dir;
    const auto path = dir / "mesh.vtm";
    std::filesystem::create_directories(path / "occupied");  // the index cannot replace a non-empty folder
    const std::string message = error_of([&] { write_mesh(testing::conforming_patch(), path); });
    EXPECT_TRUE(contains(message, "cannot replace '" + path.string() + "'")) << message;
    EXPECT_EQ(testing::entry_count(dir.path()), 1);
    testing::write_text(dir / "file", "x");
    const std::string blocked = error_of([&] { write_mesh(testing::conforming_patch(), dir / "file" / "m.vtm"); });
    EXPECT_TRUE(contains(blocked, "Not a directory")) << blocked;
    EXPECT_EQ(testing::entry_count(dir.path()), 2);
}

// In a group of outputs that fails later (destroyed uncommitted), the .vtm's folder goes with
// its files; committed, all of it stays.
TEST(VtmWriter, InAGroupItsFolderGoesWithItsFiles) {
    TempDir dir;
    {
        io::CommitGroup group;
        write_vtm(testing::conforming_patch(), dir / "m.vtm");
    }
    EXPECT_EQ(testing::entry_count(dir.path()), 0);
    {
        io::CommitGroup group;
        write_vtm(testing::conforming_patch(), dir / "m.vtm");
        group.commit();
    }
    EXPECT_EQ(testing::entry_count(dir.path()), 2);
    EXPECT_GT(testing::entry_count(dir / "m"), 3);
}

// A .vtm written over another model's: the folder keeps only the new parts (in a group, once it
// commits), and files that are no .vtu part stay.
TEST(VtmWriter, ReplacesTheEarlierModelsParts) {
    TempDir dir;
    write_vtm(testing::conforming_patch(), dir / "m.vtm");
    const int parts = testing::entry_count(dir / "m");
    testing::write_text(dir / "m" / "boundary_pipe_4.vtu", "an earlier model's part");
    testing::write_text(dir / "m" / "notes.txt", "the user's");
    {
        io::CommitGroup group;
        write_vtm(testing::conforming_patch(), dir / "m.vtm");
        EXPECT_TRUE(std::filesystem::exists(dir / "m" / "boundary_pipe_4.vtu"));  // not committed yet
        group.commit();
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "m" / "boundary_pipe_4.vtu"));
    EXPECT_TRUE(std::filesystem::exists(dir / "m" / "notes.txt"));
    EXPECT_EQ(testing::entry_count(dir / "m"), parts + 1);
}

// The multiblock names one block per region and per surface group; each file holds exactly
// its group's elements and the points they use.
TEST(VtmWriter, OneNamedBlockPerGroup) {
    TempDir dir;
    const HybridMesh mesh = testing::conforming_patch();
    write_vtm(mesh, dir / "m.vtm");
    const std::string index = testing::read_text(dir / "m.vtm");
    EXPECT_TRUE(contains(index, "type=\"vtkMultiBlockDataSet\"")) << index;
    EXPECT_TRUE(contains(index, "<Block index=\"0\" name=\"volume\">")) << index;
    EXPECT_TRUE(contains(index, "<Block index=\"1\" name=\"boundary\">")) << index;
    std::size_t blocks = 0;
    for (std::size_t at = index.find("<DataSet "); at != std::string::npos; at = index.find("<DataSet ", at + 1))
        ++blocks;
    std::size_t used = 0;  // groups with elements
    for (const std::string& r : mesh.region_names) used += contains(index, "name=\"" + r + "\"");
    EXPECT_EQ(used, mesh.region_names.size());
    EXPECT_EQ(blocks, mesh.region_names.size() + mesh.surface_group_names.size());
    // The pyramid's block: one cell, its five points.
    const std::string pyramid = testing::read_text(dir / "m" / "volume_pyramids.vtu");
    EXPECT_TRUE(contains(pyramid, "<Piece NumberOfPoints=\"5\" NumberOfCells=\"1\">")) << pyramid;
    // The hex's five boundary quads use its eight points.
    const std::string sides = testing::read_text(dir / "m" / "boundary_hex_sides.vtu");
    EXPECT_TRUE(contains(sides, "<Piece NumberOfPoints=\"8\" NumberOfCells=\"5\">")) << sides;
    EXPECT_EQ(testing::entry_count(dir / "m"), static_cast<int>(blocks));
}

// ---------------------------------------------------------------- Abaqus

TEST(AbaqusFaces, MappingOfTheTopologyTables) {
    const int tet[4] = {3, 4, 2, 1};
    for (int f = 0; f < 4; ++f) EXPECT_EQ(io::abaqus_face_number(CellKind::Tet, f), tet[f]) << f;
    for (int f = 0; f < 5; ++f) EXPECT_EQ(io::abaqus_face_number(CellKind::Pyramid, f), f + 1) << f;
    // As a collapsed brick the pyramid keeps the brick's numbers; S2 is the apex alone.
    const int collapsed[5] = {1, 3, 4, 5, 6};
    for (int f = 0; f < 5; ++f) EXPECT_EQ(io::abaqus_face_number(CellKind::Pyramid, f, true), collapsed[f]) << f;
    for (int f = 0; f < 6; ++f) EXPECT_EQ(io::abaqus_face_number(CellKind::Hex, f), f + 1) << f;
}

// The Abaqus face named for each boundary face has exactly the boundary face's nodes, with
// pyramids as C3D5 and as collapsed C3D8 (nodes 1 2 3 4 5 5 5 5).
TEST(AbaqusFaces, BoundaryFacesMapToTheirCellFaces) {
    const HybridMesh mesh = testing::mixed_grid(3);
    const auto owners = io::boundary_cell_faces(mesh);
    for (bool collapsed : {false, true})
        for (FaceKind fk : {FaceKind::Tri, FaceKind::Quad})
            for (index_t f = 0; f < mesh.face_count(fk); ++f) {
                const io::CellFaceRef ref = owners[static_cast<int>(fk)][f];
                ASSERT_NE(ref.cell, kNoIndex);
                const int s = io::abaqus_face_number(ref.kind, ref.local_face, collapsed);
                const io::AbaqusFace af = ref.kind == CellKind::Tet                   ? io::kAbaqusTetFaces[s - 1]
                                          : ref.kind == CellKind::Pyramid && !collapsed ? io::kAbaqusPyramidFaces[s - 1]
                                                                                        : io::kAbaqusHexFaces[s - 1];
                const auto cell = mesh.cell(ref.kind, ref.cell);
                std::vector<index_t> abaqus_nodes, face_nodes(mesh.face(fk, f).begin(), mesh.face(fk, f).end());
                for (int k = 0; k < af.size; ++k)
                    abaqus_nodes.push_back(cell[std::min<int>(af.node[k] - 1, static_cast<int>(cell.size()) - 1)]);
                std::sort(abaqus_nodes.begin(), abaqus_nodes.end());
                abaqus_nodes.erase(std::unique(abaqus_nodes.begin(), abaqus_nodes.end()), abaqus_nodes.end());
                std::sort(face_nodes.begin(), face_nodes.end());
                EXPECT_EQ(abaqus_nodes, face_nodes);
            }
}

TEST(InpWriter, SetsAndSurfacesOfThePatch) {
    TempDir dir;
    write_inp(testing::conforming_patch(), dir / "m.inp");
    const std::string text = testing::read_text(dir / "m.inp");
    EXPECT_TRUE(contains(text, "*ELEMENT, TYPE=C3D4, ELSET=KIND_TET\n1, ")) << text;
    // The pyramid as a brick with its apex repeated.
    EXPECT_TRUE(contains(text, "*ELEMENT, TYPE=C3D8, ELSET=KIND_PYRAMID\n11, 5, 6, 7, 8, 13, 13, 13, 13\n")) << text;
    EXPECT_TRUE(contains(text, "*ELEMENT, TYPE=C3D8, ELSET=KIND_HEX\n12, 1, 2, 3, 4, 5, 6, 7, 8\n")) << text;
    EXPECT_TRUE(contains(text, "*ELSET, ELSET=EALL, GENERATE\n1, 12, 1\n")) << text;
    EXPECT_TRUE(contains(text, "*NSET, NSET=NALL, GENERATE\n1, 13, 1\n")) << text;
    EXPECT_TRUE(contains(text, "*ELSET, ELSET=pyramids\n11\n")) << text;
    EXPECT_TRUE(contains(text, "*ELSET, ELSET=tets\n1, 2, 3, 4, 5, 6, 7, 8, 9, 10\n")) << text;
    // The hex's five boundary quads: bottom and the four sides, faces S1 and S3..S6, one
    // element set per face number for CalculiX's *FILM / *DFLUX, and the surface from them.
    for (int s : {1, 3, 4, 5, 6})
        EXPECT_TRUE(contains(text, "*ELSET, ELSET=hex_sides_S" + std::to_string(s) + "\n12\n")) << s;
    EXPECT_TRUE(contains(text, "*SURFACE, NAME=hex_sides, TYPE=ELEMENT\nhex_sides_S1, S1\nhex_sides_S3, S3\n"
                               "hex_sides_S4, S4\nhex_sides_S5, S5\nhex_sides_S6, S6\n"))
        << text;
    EXPECT_TRUE(contains(text, "*NSET, NSET=hex_sides\n1, 2, 3, 4, 5, 6, 7, 8\n")) << text;
    // hex_sides and upper_sides meet in the ring 5-6-7-8.
    EXPECT_TRUE(contains(text, "*NSET, NSET=SHARED_hex_sides_upper_sides\n5, 6, 7, 8\n")) << text;
    EXPECT_TRUE(contains(text, "** length unit: not known")) << text;
}

// A surface between two regions (an assembly's joint) seen from either side: each region's
// surface names that region's element, whichever cell the group's own sets took.
TEST(InpWriter, RegionSurfacesTakeTheirRegionsElements) {
    TempDir dir;
    HybridMesh patch = testing::conforming_patch();
    const std::array<index_t, 4> joint{4, 5, 6, 7};  // the hex's top, the pyramid's base
    patch.add_face(FaceKind::Quad, joint, patch.surface_group_id("joint"));
    const index_t joint_group = patch.surface_group_id("joint");
    MeshDescription description;
    description.region_surfaces = {{"hex_top", patch.region_id("hex_ring"), {joint_group}},
                                   {"pyramid_base", patch.region_id("pyramids"), {joint_group}}};
    WriteOptions o;
    o.description = &description;
    write_inp(patch, dir / "r.inp", o);
    const std::string text = testing::read_text(dir / "r.inp");
    // Labels: tets 1-10, the pyramid 11, the hex 12; the brick's top is S2, the pyramid's base S1.
    EXPECT_TRUE(contains(text, "*ELSET, ELSET=hex_top_S2\n12\n")) << text;
    EXPECT_TRUE(contains(text, "*SURFACE, NAME=hex_top, TYPE=ELEMENT\nhex_top_S2, S2\n")) << text;
    EXPECT_TRUE(contains(text, "*ELSET, ELSET=pyramid_base_S1\n11\n")) << text;
    EXPECT_TRUE(contains(text, "*NSET, NSET=hex_top\n5, 6, 7, 8\n")) << text;
    EXPECT_TRUE(contains(text, "*ELSET, ELSET=joint_S1\n11\n")) << text;  // the first cell that has it
}

TEST(InpWriter, FamiliesAndTheFiveNodePyramid) {
    TempDir dir;
    const HybridMesh patch = testing::conforming_patch();
    WriteOptions o;
    o.inp_family = InpFamily::HeatTransfer;
    write_inp(patch, dir / "h.inp", o);
    const std::string heat = testing::read_text(dir / "h.inp");
    EXPECT_TRUE(contains(heat, "*ELEMENT, TYPE=DC3D4, ELSET=KIND_TET\n")) << heat;
    EXPECT_TRUE(contains(heat, "*ELEMENT, TYPE=DC3D8, ELSET=KIND_PYRAMID\n")) << heat;
    // CalculiX's coupled step takes the ordinary bricks and tets; the T elements are Abaqus's.
    o.inp_family = InpFamily::Coupled;
    write_inp(patch, dir / "c.inp", o);
    const std::string coupled = testing::read_text(dir / "c.inp");
    EXPECT_TRUE(contains(coupled, "*ELEMENT, TYPE=C3D8, ELSET=KIND_HEX\n")) << coupled;
    EXPECT_TRUE(contains(coupled, "*ELEMENT, TYPE=C3D4, ELSET=KIND_TET\n")) << coupled;
    EXPECT_FALSE(contains(coupled, "TYPE=C3D8T")) << coupled;
    o.inp_family = InpFamily::CoupledAbaqus;
    write_inp(patch, dir / "a.inp", o);
    const std::string abaqus = testing::read_text(dir / "a.inp");
    EXPECT_TRUE(contains(abaqus, "*ELEMENT, TYPE=C3D8T, ELSET=KIND_HEX\n")) << abaqus;
    EXPECT_TRUE(contains(abaqus, "CalculiX refuses them")) << abaqus;
    o.inp_family = InpFamily::Stress;
    o.inp_pyramid = InpPyramid::C3D5;
    write_inp(patch, dir / "p.inp", o);
    EXPECT_TRUE(contains(testing::read_text(dir / "p.inp"), "*ELEMENT, TYPE=C3D5, ELSET=KIND_PYRAMID\n11, 5, 6, 7, 8, 13\n"));
    o.inp_family = InpFamily::HeatTransfer;
    const std::string message = error_of([&] { write_inp(patch, dir / "x.inp", o); });
    EXPECT_TRUE(contains(message, "C3D5 has no heat-transfer")) << message;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.inp"));
}

// CalculiX reads at most 20 characters of a number and misreads a 21-character one.
TEST(InpWriter, NumbersFitTwentyCharactersAndRoundOffIsZero) {
    char text[32];
    auto written = [&](double v, double zero_below) {
        return std::string(text, io::abaqus_number(v, zero_below, text));
    };
    EXPECT_EQ(written(12.345678901234567, 0), "12.345678901234567");  // fits: exact
    EXPECT_EQ(written(0.5, 0), "0.5");
    for (double v : {1.234567890123456e-05, -1.2345678901234567e-100, -9.876543210987654e+300, 5.169878828456423e-26}) {
        const std::string s = written(v, 0);
        EXPECT_LE(s.size(), 20u) << s;
        EXPECT_NEAR(std::stod(s), v, std::abs(v) * 1e-11) << s;  // 13 or more digits
    }
    EXPECT_EQ(written(5.169878828456423e-26, 1e-11), "0");
    EXPECT_EQ(written(-4.0389678347315804e-28, 1e-11), "0");
    EXPECT_EQ(written(2e-11, 1e-11), "2e-11");

    // In a file: round-off beside a model of size about 1 becomes 0.
    TempDir dir;
    HybridMesh mesh = testing::conforming_patch();
    mesh.x[0] = 4.0389678347315804e-28;
    mesh.y[0] = -1.234567890123456e-05;
    write_inp(mesh, dir / "m.inp");
    const std::string inp = testing::read_text(dir / "m.inp");
    EXPECT_TRUE(contains(inp, "*NODE\n1, 0, -1.2345678901235e-05, ")) << inp.substr(0, 2000);
}

TEST(InpWriter, FaceOfNoCellIsAnErrorAndLeavesNoFile) {
    TempDir dir;
    HybridMesh mesh = testing::conforming_patch();
    const std::array<index_t, 3> stray{0, 1, 12};
    mesh.add_face(FaceKind::Tri, stray, 0);
    const std::string message = error_of([&] { write_inp(mesh, dir / "m.inp"); });
    EXPECT_TRUE(contains(message, "boundary triangle 10 (surface group \"hex_sides\") is not a face of any cell"))
        << message;
    EXPECT_EQ(testing::entry_count(dir.path()), 0);
}

TEST(AbaqusLabels, ValidDistinctLabels) {
    io::AbaqusLabels labels;
    EXPECT_EQ(labels.label("hex_ring"), "hex_ring");
    EXPECT_EQ(labels.label("HEX_RING"), "HEX_RING_2");  // Abaqus ignores case
    EXPECT_EQ(labels.label("pipe 1, inner"), "pipe_1__inner");
    EXPECT_EQ(labels.label("3rd face"), "G_3rd_face");
    EXPECT_EQ(labels.label(""), "G_");
    EXPECT_EQ(labels.label(std::string(100, 'a')).size(), 80u);
    EXPECT_EQ(labels.label(std::string(100, 'a')), std::string(78, 'a') + "_2");
}

}  // namespace
}  // namespace tubemesh
