#pragma once
// Outside readers for the mesh file tests: the Python scripts in tests/scripts open a file
// with Gmsh or meshio and print JSON; these helpers run them and state what they should see
// for a given mesh. Header-only: every test target that links support/process.cpp can use it.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"
#include "tests/support/process.hpp"

namespace tubemesh::testing {

using Counts = std::map<std::string, int>;

// Runs tests/scripts/<script> with Debian's Python and parses its JSON output; a failing
// script is a test failure and gives an empty object.
inline nlohmann::json run_script(const std::string& script, std::vector<std::string> args) {
    args.insert(args.begin(), std::string(TUBEMESH_TEST_SCRIPTS) + "/" + script);
    std::string command = shell_quote(TUBEMESH_TEST_PYTHON);
    for (const std::string& a : args) {
        command += ' ';
        command += shell_quote(a);
    }
    const ProcessResult r = run_command(command);
    if (r.exit_code != 0) {
        ADD_FAILURE() << script << " failed (exit " << r.exit_code << "):\n" << r.err;
        return nlohmann::json::object();
    }
    return nlohmann::json::parse(r.out);
}

inline bool listed(const nlohmann::json& array, const std::string& name) {
    return std::find(array.begin(), array.end(), nlohmann::json(name)) != array.end();
}

// Gmsh's element counts per type number, as tubemesh's mesh has them.
inline Counts gmsh_counts(const HybridMesh& m) {
    Counts c;
    auto put = [&](const char* type, index_t n) {
        if (n > 0) c[type] = static_cast<int>(n);
    };
    put("4", m.cell_count(CellKind::Tet));
    put("7", m.cell_count(CellKind::Pyramid));
    put("5", m.cell_count(CellKind::Hex));
    put("2", m.face_count(FaceKind::Tri));
    put("3", m.face_count(FaceKind::Quad));
    return c;
}

// [dim, tag, name] per physical group, as Gmsh lists them (by dimension, then tag).
inline nlohmann::json physical_groups(const HybridMesh& m) {
    nlohmann::json groups = nlohmann::json::array();
    for (std::size_t g = 0; g < m.surface_group_names.size(); ++g)
        groups.push_back({2, g + 1, m.surface_group_names[g]});
    for (std::size_t r = 0; r < m.region_names.size(); ++r) groups.push_back({3, r + 1, m.region_names[r]});
    return groups;
}

// meshio's cell counts per cell type. The .vtu holds the boundary faces too, the .inp only
// the cells (its surfaces are faces of cells).
// meshio's cell counts per type: of a .vtu (the volume cells) or of a .inp, whose pyramids
// are bricks with the apex repeated.
inline Counts meshio_counts(const HybridMesh& m, bool inp) {
    Counts c;
    auto put = [&](const char* type, index_t n) {
        if (n > 0) c[type] += static_cast<int>(n);
    };
    put("tetra", m.cell_count(CellKind::Tet));
    put(inp ? "hexahedron" : "pyramid", m.cell_count(CellKind::Pyramid));
    put("hexahedron", m.cell_count(CellKind::Hex));
    return c;
}

// Elements per group, keyed "dim:name" like group_members.py; groups without elements are
// left out (Gmsh does not list them either).
inline Counts group_sizes(const HybridMesh& m) {
    Counts c;
    for (CellKind k : kAllCellKinds)
        for (index_t r : m.block(k).region) ++c["3:" + m.region_names[r]];
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
        for (index_t g : m.block(k).group) ++c["2:" + m.surface_group_names[g]];
    return c;
}

// The .vtu's field data: group name -> [id, dim], regions first (vtu_writer.cpp), for a mesh
// whose names are all distinct.
inline nlohmann::json vtu_field_data(const HybridMesh& m) {
    nlohmann::json f = nlohmann::json::object();
    for (std::size_t r = 0; r < m.region_names.size(); ++r) f[m.region_names[r]] = {r, 3};
    for (std::size_t g = 0; g < m.surface_group_names.size(); ++g) f[m.surface_group_names[g]] = {g, 2};
    return f;
}

}  // namespace tubemesh::testing
