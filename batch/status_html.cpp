#include "batch/status_html.hpp"

#include <nlohmann/json.hpp>

#include "job/html_assets.hpp"
#include "job/html_report.hpp"

namespace tubemesh::batch {

std::string status_html(const std::vector<BlockRecord>& rows) {
    nlohmann::json blocks = nlohmann::json::array();
    for (const BlockRecord& r : rows) {
        std::string html;
        for (const OutputFile& f : r.outputs)
            if (f.path.size() > 5 && f.path.ends_with(".html")) html = f.path;
        blocks.push_back({{"id", r.id},
                          {"status", r.status},
                          {"error", r.error},
                          {"elements", r.elements()},
                          {"hexes", r.hexes},
                          {"pyramids", r.pyramids},
                          {"tets", r.tets},
                          {"seconds", r.seconds},
                          {"tet_min", r.tet_collapse.min},
                          {"tet_mean", r.tet_collapse.mean},
                          {"pyramid_min", r.pyramid_jacobian.min},
                          {"hex_min", r.hex_jacobian.min},
                          {"hex_condition_max", r.hex_condition_max},
                          {"html", html}});
    }
    const job::HtmlAssets& a = job::html_assets();
    return job::html_page(a.batch_body, {{"blocks", blocks}}, {a.chart_js, a.batch_js});
}

}  // namespace tubemesh::batch
