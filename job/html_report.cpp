#include "job/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "job/cut_view.hpp"
#include "job/html_assets.hpp"
#include "job/mesh_report.hpp"
#include "job/quality_measures.hpp"

namespace tubemesh::job {

namespace {

// Finer than the report's 10 classes: the page has room.
constexpr int kClasses = 20;

nlohmann::json histogram_json(const QualityMeasure& m, const std::vector<double>& values) {
    std::vector<index_t> counts(kClasses, 0);
    double lo = 0, hi = 0, sum = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double v = values[i];
        lo = i == 0 ? v : std::min(lo, v);
        hi = i == 0 ? v : std::max(hi, v);
        sum += v;
        const double t = (v - m.lo) / (m.hi - m.lo) * kClasses;
        const int c = std::isfinite(t) ? std::clamp(static_cast<int>(std::floor(t)), 0, kClasses - 1)
                                       : (m.higher_is_better ? 0 : kClasses - 1);
        ++counts[c];
    }
    return {{"kind", m.kind_key},          {"key", m.key},
            {"label", m.label},            {"lo", m.lo},
            {"hi", m.hi},                  {"higher_is_better", m.higher_is_better},
            {"count", values.size()},      {"min", lo},
            {"max", hi},                   {"mean", values.empty() ? 0.0 : sum / values.size()},
            {"counts", counts}};
}

nlohmann::json table_json(const geom::MeshRun& run) {
    nlohmann::json rows = nlohmann::json::array();
    for (const TableRow& r : run_table_rows(run)) rows.push_back({r.kind, r.label, r.value});
    return rows;
}

// JSON inside a <script> element: no "</script>" or "<!--" may appear in it.
std::string script_safe(std::string json) {
    std::string out;
    out.reserve(json.size());
    for (char c : json) {
        if (c == '<')
            out += "\\u003c";
        else
            out += c;
    }
    return out;
}

}  // namespace

std::string html_report(const geom::MeshRun& run) {
    const HybridMesh& mesh = run.result.mesh;
    nlohmann::json histograms = nlohmann::json::array();
    std::array<std::vector<double>, kCellKindCount> primary;
    for (const QualityMeasure& m : quality_measures()) {
        std::vector<double> values = m.values(mesh);
        if (!values.empty()) histograms.push_back(histogram_json(m, values));
        if (&m == &primary_measure(m.kind)) primary[static_cast<int>(m.kind)] = std::move(values);
    }
    const nlohmann::json data = {{"report", run_json(run, {})},
                                 {"table", table_json(run)},
                                 {"table_legend", kTableLegend},
                                 {"histograms", histograms},
                                 {"view", cut_view_json(run, primary)}};

    const HtmlAssets& a = html_assets();
    return html_page(a.page_body, data, {a.three_js, a.orbit_controls_js, a.chart_js, a.page_js});
}

std::string html_page(std::string_view body, const nlohmann::json& data, std::initializer_list<std::string_view> scripts) {
    const HtmlAssets& a = html_assets();
    std::string page;
    page.reserve(a.three_js.size() + a.chart_js.size() + (1 << 20));
    page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += "<title>tubemesh report</title>\n";  // the page's script names the source
    page += "<style>\n";
    page += a.page_css;
    page += "</style>\n</head>\n<body>\n";
    page += body;
    page += "<script type=\"application/json\" id=\"tubemesh-data\">";
    page += script_safe(data.dump());
    page += "</script>\n";
    for (std::string_view js : scripts) {
        page += "<script>\n";
        page += js;
        page += "\n</script>\n";
    }
    page += "</body>\n</html>\n";
    return page;
}

}  // namespace tubemesh::job
