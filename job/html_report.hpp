#pragma once
// The report of a meshing run as one self-contained HTML page (no network needed to view it):
// the run's summary and Table 1, a histogram of every quality measure per kind
// (quality_measures.hpp), the phases' times as bars, and a 3D view of a cut through the hybrid
// layer around the first pipe (cut_view.hpp) coloured by kind or by quality with the worst cells
// marked. Drawn by three.js and Chart.js from Debian, inlined at build time (html_assets.hpp).
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "geom/mesh_file.hpp"

namespace tubemesh::job {

std::string html_report(const geom::MeshRun& run);

// A self-contained page in the reports' style: `body`, then `data` as the JSON element
// "tubemesh-data" the scripts read, then the scripts inlined in order.
std::string html_page(std::string_view body, const nlohmann::json& data, std::initializer_list<std::string_view> scripts);

}  // namespace tubemesh::job
