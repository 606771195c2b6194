#pragma once
// The files the HTML report inlines, embedded in the program at build time: three.js and its
// OrbitControls (Debian's libjs-three) and Chart.js (libjs-chart.js), so a report opens
// without network, and the pages' own scripts, style and bodies (job/html/).
#include <string_view>

namespace tubemesh::job {

struct HtmlAssets {
    std::string_view three_js, orbit_controls_js, chart_js;
    std::string_view page_js, page_css, page_body;  // a run's report
    std::string_view batch_js, batch_body;          // a batch's report (same style)
};

const HtmlAssets& html_assets();

}  // namespace tubemesh::job
