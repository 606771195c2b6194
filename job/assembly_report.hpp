#pragma once
// The report of an assembly run beside the whole mesh's (mesh_report.hpp): Table 1 with a column
// per solid and one for the whole, each solid's volume against the CAD's, the shared faces and
// the volume check over the whole.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geom/assembly/mesh_assembly.hpp"

namespace tubemesh::job {

// `whole` is the run's mesh and report: run.run, or where the caller moved it.

// The mesh's volume against the sum of its solids' (equal when no cell is counted twice or
// lost), over the sum.
double volume_mismatch(const geom::AssemblyRun& run, const geom::MeshRun& whole);

// Table 1 per solid and in total, as text.
std::vector<std::string> assembly_lines(const geom::AssemblyRun& run, const geom::MeshRun& whole);

// The same as JSON: {"solids": [...], "shared_faces", "shared_triangles", "glue_tolerance", ...}.
nlohmann::json assembly_json(const geom::AssemblyRun& run, const geom::MeshRun& whole);

}  // namespace tubemesh::job
