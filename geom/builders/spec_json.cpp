#include "geom/builders/spec_json.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "engine/core/types.hpp"
#include "geom/builders/serpentine.hpp"

namespace tubemesh::geom {

namespace {

using nlohmann::json;

struct Context {
    std::string source;
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(source + ": " + (where.empty() ? "" : where + ": ") + what);
    }
};

void only_keys(const json& j, const std::set<std::string>& known, const std::string& where, const Context& ctx) {
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (known.count(it.key())) continue;
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        ctx.fail(where, "unknown key '" + it.key() + "' (known: " + list + ")");
    }
}

double number(const json& j, const std::string& where, const Context& ctx) {
    if (!j.is_number()) ctx.fail(where, "expected a number, got " + j.dump());
    return j.get<double>();
}

Vec3 vec3(const json& j, const std::string& where, const Context& ctx) {
    if (!j.is_array() || j.size() != 3) ctx.fail(where, "expected [x, y, z], got " + j.dump());
    return {number(j[0], where + "[0]", ctx), number(j[1], where + "[1]", ctx), number(j[2], where + "[2]", ctx)};
}

bool flag(const json& j, const std::string& where, const Context& ctx) {
    if (!j.is_boolean()) ctx.fail(where, "expected true or false, got " + j.dump());
    return j.get<bool>();
}

std::string text(const json& j, const std::string& where, const Context& ctx) {
    if (!j.is_string()) ctx.fail(where, "expected a string, got " + j.dump());
    return j.get<std::string>();
}

PathKind path_kind(const std::string& s, const std::string& where, const Context& ctx) {
    if (s == "line") return PathKind::Line;
    if (s == "arc") return PathKind::Arc;
    if (s == "polyline") return PathKind::Polyline;
    if (s == "spline") return PathKind::Spline;
    if (s == "bspline") return PathKind::Bspline;
    ctx.fail(where, "unknown path '" + s + "' (use line, arc, polyline, spline or bspline)");
}

const char* path_name(PathKind k) {
    switch (k) {
        case PathKind::Line: return "line";
        case PathKind::Arc: return "arc";
        case PathKind::Polyline: return "polyline";
        case PathKind::Spline: return "spline";
        case PathKind::Bspline: return "bspline";
    }
    return "?";
}

PipeSpec pipe_from(const json& j, const std::string& where, const Context& ctx) {
    if (!j.is_object()) ctx.fail(where, "expected an object {\"path\": ..., \"diameter\": ..., \"points\": [...]}");
    only_keys(j, {"path", "diameter", "points", "bend_radius", "start_tangent", "end_tangent", "blind"}, where, ctx);
    PipeSpec p;
    if (!j.contains("diameter")) ctx.fail(where, "missing \"diameter\"");
    if (!j.contains("points")) ctx.fail(where, "missing \"points\"");
    p.kind = j.contains("path") ? path_kind(text(j["path"], where + ".path", ctx), where + ".path", ctx) : PathKind::Spline;
    p.diameter = number(j["diameter"], where + ".diameter", ctx);
    const json& pts = j["points"];
    if (!pts.is_array()) ctx.fail(where + ".points", "expected a list of [x, y, z]");
    for (std::size_t i = 0; i < pts.size(); ++i) p.points.push_back(vec3(pts[i], where + ".points[" + std::to_string(i) + "]", ctx));
    if (j.contains("bend_radius")) p.bend_radius = number(j["bend_radius"], where + ".bend_radius", ctx);
    if (j.contains("start_tangent")) p.start_tangent = vec3(j["start_tangent"], where + ".start_tangent", ctx);
    if (j.contains("end_tangent")) p.end_tangent = vec3(j["end_tangent"], where + ".end_tangent", ctx);
    if (j.contains("blind")) p.blind = flag(j["blind"], where + ".blind", ctx);
    if (p.blind && p.kind != PathKind::Line) ctx.fail(where + ".blind", "only a line can be blind");
    return p;
}

SerpentineParams serpentine_from(const json& j, const Context& ctx) {
    const std::string where = "serpentine";
    if (!j.is_object()) ctx.fail(where, "expected an object");
    only_keys(j, {"size", "diameter", "spacing", "bend_radius", "end_margin", "inlet", "outlet"}, where, ctx);
    SerpentineParams p;
    if (j.contains("size")) p.size = vec3(j["size"], where + ".size", ctx);
    if (j.contains("diameter")) p.diameter = number(j["diameter"], where + ".diameter", ctx);
    if (j.contains("spacing")) p.spacing = number(j["spacing"], where + ".spacing", ctx);
    if (j.contains("bend_radius")) p.bend_radius = number(j["bend_radius"], where + ".bend_radius", ctx);
    if (j.contains("end_margin")) p.end_margin = number(j["end_margin"], where + ".end_margin", ctx);
    if (j.contains("inlet")) p.inlet = text(j["inlet"], where + ".inlet", ctx);
    if (j.contains("outlet")) p.outlet = text(j["outlet"], where + ".outlet", ctx);
    return p;
}

}  // namespace

BlockSpec parse_block_spec(const std::string& input, const std::string& source) {
    const Context ctx{source};
    json j;
    try {
        j = json::parse(input);
    } catch (const json::exception& e) {  // parse_error, or out_of_range for a number like 1e99999
        ctx.fail("", std::string("not valid JSON (") + e.what() + ")");
    }
    if (!j.is_object()) ctx.fail("", "expected a JSON object with \"box\" or \"cylinder\" and \"pipes\", or \"serpentine\"");
    only_keys(j, {"name", "unit", "box", "cylinder", "pipes", "serpentine", "check_clearance"}, "", ctx);

    const std::string name = j.contains("name") ? text(j["name"], "name", ctx) : std::filesystem::path(source).stem().string();
    const std::string unit = j.contains("unit") ? text(j["unit"], "unit", ctx) : "model units";
    if (j.contains("serpentine")) {
        if (j.contains("box") || j.contains("cylinder") || j.contains("pipes"))
            ctx.fail("", "\"serpentine\" describes the whole block: leave out \"box\", \"cylinder\" and \"pipes\"");
        SerpentineParams params = serpentine_from(j["serpentine"], ctx);
        params.length_unit = j.contains("unit") ? unit : params.length_unit;
        return serpentine_spec(params, name);
    }

    BlockSpec spec;
    spec.name = name;
    spec.length_unit = unit;
    if (j.contains("check_clearance")) spec.check_clearance = flag(j["check_clearance"], "check_clearance", ctx);
    if (j.contains("box") == j.contains("cylinder")) ctx.fail("", "give exactly one of \"box\": [x, y, z] or \"cylinder\"");
    if (j.contains("box")) {
        spec.host.kind = HostSpec::Kind::Box;
        spec.host.size = vec3(j["box"], "box", ctx);
    } else {
        const json& c = j["cylinder"];
        if (!c.is_object() || !c.contains("diameter") || !c.contains("length"))
            ctx.fail("cylinder", "expected {\"diameter\": D, \"length\": L}");
        only_keys(c, {"diameter", "length"}, "cylinder", ctx);
        spec.host.kind = HostSpec::Kind::Cylinder;
        spec.host.diameter = number(c["diameter"], "cylinder.diameter", ctx);
        spec.host.length = number(c["length"], "cylinder.length", ctx);
    }
    if (!j.contains("pipes") || !j["pipes"].is_array())
        ctx.fail("pipes", "expected a list of pipes ([] for a block without any)");
    for (std::size_t i = 0; i < j["pipes"].size(); ++i)
        spec.pipes.push_back(pipe_from(j["pipes"][i], "pipes[" + std::to_string(i) + "]", ctx));
    return spec;
}

BlockSpec read_block_spec(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open block spec '" + path.string() + "': no such file or not readable");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return parse_block_spec(buffer.str(), path.string());
}

std::string block_spec_json(const BlockSpec& spec) {
    // One pipe per line with its points inline: nlohmann's indented dump puts every coordinate
    // on a line of its own, which makes a spec of a few pipes hundreds of lines long.
    using ordered = nlohmann::ordered_json;
    auto vec = [](const Vec3& v) { return ordered::array({v.x, v.y, v.z}); };
    std::string out = "{\n";
    out += "  \"name\": " + ordered(spec.name).dump() + ",\n";
    out += "  \"unit\": " + ordered(spec.length_unit).dump() + ",\n";
    if (!spec.check_clearance) out += "  \"check_clearance\": false,\n";
    if (spec.host.kind == HostSpec::Kind::Box)
        out += "  \"box\": " + vec(spec.host.size).dump() + ",\n";
    else
        out += "  \"cylinder\": " + ordered({{"diameter", spec.host.diameter}, {"length", spec.host.length}}).dump() + ",\n";
    out += "  \"pipes\": [\n";
    for (std::size_t i = 0; i < spec.pipes.size(); ++i) {
        const PipeSpec& p = spec.pipes[i];
        ordered pj;
        pj["path"] = path_name(p.kind);
        pj["diameter"] = p.diameter;
        if (p.kind == PathKind::Polyline) pj["bend_radius"] = p.bend_radius;
        ordered pts = ordered::array();
        for (const Vec3& v : p.points) pts.push_back(vec(v));
        pj["points"] = pts;
        if (p.start_tangent) pj["start_tangent"] = vec(*p.start_tangent);
        if (p.end_tangent) pj["end_tangent"] = vec(*p.end_tangent);
        if (p.blind) pj["blind"] = true;
        out += "    " + pj.dump() + (i + 1 < spec.pipes.size() ? ",\n" : "\n");
    }
    out += "  ]\n}";
    return out;
}

}  // namespace tubemesh::geom
