#pragma once
// The Python side of one meshing run: the run itself (mesh store and report) and the numpy
// views of its arrays. The arrays view the HybridMesh's own vectors (no copy; read-only, so
// the mesh written by write() is the mesh that was made) and keep this object alive as their
// base. The store holds x, y and z apart, so `nodes` (n x 3) is the one copy, made on first use.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>
#include <optional>

#include "geom/assembly/mesh_assembly.hpp"
#include "geom/mesh_file.hpp"

namespace tubemesh::python {

struct MeshResult {
    geom::MeshRun run;
    std::optional<geom::AssemblyRun> assembly;  // mesh(assembly=True): per solid, for the report
    nlohmann::json given;                       // the options mesh() was given: write()'s defaults
    pybind11::object nodes, quality, report, groups;  // made on first use
};

// Registers the MeshResult class ("Mesh") on the module.
void bind_mesh_result(pybind11::module_& m);

}  // namespace tubemesh::python
