#include "batch/status.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

namespace tubemesh::batch {

namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string number(double v) { return fmt::format("{}", v); }

// A measure of a kind the block has no cells of is blank, not a 0 that reads as a flat cell.
std::string measure(std::int64_t cells, double v) { return cells > 0 ? number(v) : std::string(); }

// The row with the smallest value of `measure` among done blocks that have cells of the kind.
const BlockRecord* worst(const std::vector<BlockRecord>& rows, const std::function<bool(const BlockRecord&)>& has,
                         const std::function<double(const BlockRecord&)>& measure) {
    const BlockRecord* w = nullptr;
    for (const BlockRecord& r : rows)
        if (r.status == "done" && has(r) && (!w || measure(r) < measure(*w))) w = &r;
    return w;
}

}  // namespace

std::string status_text(const std::vector<BlockRecord>& rows) {
    int done = 0, failed = 0, pending = 0;
    std::int64_t hexes = 0, pyramids = 0, tets = 0, nodes = 0;
    double seconds = 0;
    for (const BlockRecord& r : rows) {
        done += r.status == "done";
        failed += r.status == "failed";
        pending += r.status == "pending";
        if (r.status != "done") continue;
        hexes += r.hexes;
        pyramids += r.pyramids;
        tets += r.tets;
        nodes += r.nodes;
        seconds += r.seconds;
    }
    const std::int64_t elements = hexes + pyramids + tets;
    std::string out = fmt::format("{} blocks: {} done, {} failed, {} pending\n", rows.size(), done, failed, pending);
    out += fmt::format("{} elements ({} hexahedra, {} pyramids, {} tetrahedra), {} nodes\n", elements, hexes, pyramids,
                       tets, nodes);
    out += fmt::format("{:.1f} s of block time, {:.0f} elements/s per block\n", seconds,
                       seconds > 0 ? elements / seconds : 0.0);
    auto line = [&](const char* what, const BlockRecord* w, double v) {
        if (w) out += fmt::format("worst {} {:.4f} in {}\n", what, v, w->id);
    };
    if (const auto* w = worst(rows, [](const BlockRecord& r) { return r.tets > 0; },
                              [](const BlockRecord& r) { return r.tet_collapse.min; }))
        line("tet collapse", w, w->tet_collapse.min);
    if (const auto* w = worst(rows, [](const BlockRecord& r) { return r.pyramids > 0; },
                              [](const BlockRecord& r) { return r.pyramid_jacobian.min; }))
        line("pyramid scaled Jacobian", w, w->pyramid_jacobian.min);
    if (const auto* w = worst(rows, [](const BlockRecord& r) { return r.hexes > 0; },
                              [](const BlockRecord& r) { return r.hex_jacobian.min; }))
        line("hex J_m", w, w->hex_jacobian.min);
    if (const auto* w = worst(rows, [](const BlockRecord& r) { return r.hexes > 0; },
                              [](const BlockRecord& r) { return -r.hex_condition_max; }))
        line("hex condition number", w, w->hex_condition_max);
    for (const BlockRecord& r : rows)
        if (r.status == "failed") out += fmt::format("failed {}: {}\n", r.id, r.error);
    for (const BlockRecord& r : rows)
        if (r.status == "pending" && !r.error.empty()) out += fmt::format("to redo {}: {}\n", r.id, r.error);
    return out;
}

std::string status_csv(const std::vector<BlockRecord>& rows) {
    std::vector<std::string> phases;
    for (const BlockRecord& r : rows)
        for (const auto& [name, seconds] : r.phases)
            if (std::find(phases.begin(), phases.end(), name) == phases.end()) phases.push_back(name);

    std::string out =
        "id,status,error,input_sha256,options_sha256,nodes,hexes,pyramids,tets,tet_collapse_min,tet_collapse_mean,"
        "pyramid_scaled_jacobian_min,pyramid_scaled_jacobian_mean,hex_scaled_jacobian_min,hex_scaled_jacobian_mean,"
        "hex_condition_max,seconds";
    for (const std::string& p : phases) out += ",seconds_" + p;
    out += ",outputs,report,worker\n";
    for (const BlockRecord& r : rows) {
        std::string files;
        for (const OutputFile& f : r.outputs) {
            if (!files.empty()) files += ';';
            files += f.path + "=" + f.sha256;
        }
        std::vector<std::string> fields = {r.id,
                                           r.status,
                                           r.error,
                                           r.input_hash,
                                           r.options_hash,
                                           std::to_string(r.nodes),
                                           std::to_string(r.hexes),
                                           std::to_string(r.pyramids),
                                           std::to_string(r.tets),
                                           measure(r.tets, r.tet_collapse.min),
                                           measure(r.tets, r.tet_collapse.mean),
                                           measure(r.pyramids, r.pyramid_jacobian.min),
                                           measure(r.pyramids, r.pyramid_jacobian.mean),
                                           measure(r.hexes, r.hex_jacobian.min),
                                           measure(r.hexes, r.hex_jacobian.mean),
                                           measure(r.hexes, r.hex_condition_max),
                                           number(r.seconds)};
        for (const std::string& p : phases) {
            const auto it = std::find_if(r.phases.begin(), r.phases.end(), [&](const auto& ph) { return ph.first == p; });
            fields.push_back(it == r.phases.end() ? "" : number(it->second));
        }
        fields.push_back(files);
        fields.push_back(r.report);
        fields.push_back(r.worker);
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (i > 0) out += ',';
            out += csv_field(fields[i]);
        }
        out += '\n';
    }
    return out;
}

}  // namespace tubemesh::batch
