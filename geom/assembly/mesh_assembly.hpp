#pragma once
// The one-call API for assemblies: several solids sharing faces in, one conforming hybrid mesh
// and a report per solid and in total out (engine/pipeline/assembly_pipeline.hpp does the
// meshing, face first).
//
// Each solid is prepared on its own (tube recognition, sizes, discretisation; geom/prepare.hpp)
// at one S for all (the given one, else the smallest of the solids' defaults: a shared face is
// meshed once, at one size); each keeps its own St. The ids are then carried to the
// assembly's numbering, every edge is cut once, and every face gets one SurfaceMap, oriented as
// the first solid that has it sees it. No OpenCASCADE header here.
#include <string>
#include <vector>

#include "engine/pipeline/assembly_pipeline.hpp"
#include "geom/assembly/assembly.hpp"
#include "geom/mesh_file.hpp"

namespace tubemesh::geom {

struct AssemblyRun {
    MeshRun run;  // the whole mesh and report, as for one solid (run.tubes: over all solids)
    std::vector<SolidSummary> solids;
    std::vector<double> cad_volumes;  // per solid, OpenCASCADE's
    index_t shared_triangles = 0;
    AssemblyReport report;
};

AssemblyRun mesh_assembly(const Assembly& assembly, const MeshOptions& options = {});

// import_assembly, then mesh_assembly; the import is the first phase.
AssemblyRun mesh_assembly_file(const std::string& path, const MeshOptions& options = {},
                               const AssemblyOptions& assembly = {});

}  // namespace tubemesh::geom
