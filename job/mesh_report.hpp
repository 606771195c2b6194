#pragma once
// The report of a meshing run, for `tubemesh mesh` and the Python module alike: the phase lines
// and Table 1 as text, and the same as JSON (--report FILE, `report` in Python). Both are built
// from geom::MeshRun only.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geom/mesh_file.hpp"
#include "job/quality_table.hpp"

namespace tubemesh::job {

// "sweep      0.043 s  1 tubes, 8952 nodes, ...; min J_m 0.9239, max cond 2.387", one per phase.
std::vector<std::string> phase_lines(const geom::MeshRun& run);
// Table 1 with per-kind times, total time and elements per second, then the histograms; for
// one of the paper's examples, the paper's column beside this mesh's (paper_table.hpp).
std::string run_table(const geom::MeshRun& run);
// The length unit and where each surface group is (alias, CAD kind, area, centroid, normal),
// then the named node sets: what every mesh file's comment block says too.
std::vector<std::string> group_lines(const geom::MeshRun& run);
// The same table's rows with the totals (quality_table.hpp), for other renderings.
std::vector<TableRow> run_table_rows(const geom::MeshRun& run);
// Everything above as one object: source, the solid's name, stage, sizes, counts, the pipes
// (each one's wall area, share under a hex ring, ring thickness range and reason) and the share of
// all pipe wall under rings, phases, quality, check, warnings, outputs, and "paper_table1" for
// one of the paper's examples.
nlohmann::json run_json(const geom::MeshRun& run, const std::vector<std::string>& outputs);

}  // namespace tubemesh::job
