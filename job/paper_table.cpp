#include "job/paper_table.hpp"

#include <fmt/format.h>

namespace tubemesh::job {

namespace {

// Wang et al., Table 1 and section 6 (../shared/paper.md).
constexpr PaperExample kExamples[] = {
    {"paper-ex1", 1, 1432, 716, 56446, 13607, 0.362795, 0.819253, 0.563902, 0.761018, 0.669033, 0.702369, 1.413770,
     1.446319, 1061195},
    {"paper-ex2", 2, 320, 160, 8932, 2584, 0.303524, 0.800367, 0.450880, 0.736676, 0.644548, 0.701924, 1.384605,
     1.451690, 68154},
    {"paper-ex3", 3, 56, 56, 6885, 1778, 0.258356, 0.811476, 0.369464, 0.789080, 0.498896, 0.696258, 1.533187,
     1.774295, 21496},
};

std::string value_text(double v, bool whole) { return whole ? fmt::format("{}", v) : fmt::format("{:.6f}", v); }

}  // namespace

const PaperExample* paper_example(std::string_view solid_name) {
    for (const PaperExample& e : kExamples)
        if (solid_name == e.name) return &e;
    return nullptr;
}

std::vector<PaperRow> paper_rows(const PaperExample& p, const QualitySummary& q, index_t nodes) {
    const double hexes = q.hex_scaled_jacobian.count, pyramids = q.pyramid_jacobian.count, tets = q.tet_collapse.count;
    auto measure = [](const MeasureSummary& m, double v) { return m.count ? std::optional<double>(v) : std::nullopt; };
    return {
        {"elements", "Elements", double(p.hexes + p.pyramids + p.tets), hexes + pyramids + tets, true},
        {"tets", "  tetrahedra", double(p.tets), tets, true},
        {"pyramids", "  pyramids", double(p.pyramids), pyramids, true},
        {"hexes", "  hexahedra", double(p.hexes), hexes, true},
        {"nodes", "Nodes", double(p.nodes), double(nodes), true},
        {"tet_collapse_min", "Tet collapse min", p.tet_min, measure(q.tet_collapse, q.tet_collapse.min)},
        {"tet_collapse_mean", "Tet collapse avg", p.tet_mean, measure(q.tet_collapse, q.tet_collapse.mean)},
        {"pyramid_min", "Pyramid min", p.pyramid_min, measure(q.pyramid_jacobian, q.pyramid_jacobian.min)},
        {"pyramid_mean", "Pyramid avg", p.pyramid_mean, measure(q.pyramid_jacobian, q.pyramid_jacobian.mean)},
        {"hex_jm_min", "Hex J_m min", p.jm_min, measure(q.hex_scaled_jacobian, q.hex_scaled_jacobian.min)},
        {"hex_jm_mean", "Hex J_m avg", p.jm_mean, measure(q.hex_scaled_jacobian, q.hex_scaled_jacobian.mean)},
        {"hex_cond_min", "Hex Cond min", p.cond_min, measure(q.hex_condition, q.hex_condition.min)},
        {"hex_cond_mean", "Hex Cond avg", p.cond_mean, measure(q.hex_condition, q.hex_condition.mean)},
        {"all_tet_reference", "All-tet mesher's tets", double(p.all_tet), std::nullopt, true},
    };
}

std::string format_paper_table(const PaperExample& p, const std::vector<PaperRow>& rows) {
    std::string out = fmt::format("Paper's Table 1, Example {} ({}), beside this mesh:\n", p.number, p.name);
    out += fmt::format("{:<24} {:>12} {:>12}\n", "", "paper", "this mesh");
    for (const PaperRow& r : rows)
        out += fmt::format("{:<24} {:>12} {:>12}\n", r.label, value_text(r.paper, r.whole),
                           r.ours ? value_text(*r.ours, r.whole) : "-");
    out += "(pyramids: the paper's Q_p, ours Verdict's scaled Jacobian; all-tet: Hypermesh in the paper)\n";
    return out;
}

nlohmann::json paper_table_json(const PaperExample& p, const std::vector<PaperRow>& rows) {
    nlohmann::json list = nlohmann::json::array();
    for (const PaperRow& r : rows)
        list.push_back({{"key", r.key},
                        {"label", r.label},
                        {"paper", r.paper},
                        {"this_mesh", r.ours ? nlohmann::json(*r.ours) : nlohmann::json(nullptr)}});
    return {{"example", p.number}, {"preset", p.name}, {"rows", list}};
}

}  // namespace tubemesh::job
