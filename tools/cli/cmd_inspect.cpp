// `tubemesh inspect FILE [--json] [--size S] [--sweep-size ST] [--solid N]`: what tubemesh sees
// in a CAD file before meshing it. The faces and their roles, the tubes found (radius, length,
// bend, hosts), the candidates that were not tubes and why, and the S / St plan with every
// change the sizing rules made, and the lower bound on the element count at those sizes (the
// one `tubemesh mesh` refuses sizes on). Exit 0, or 2 when the file cannot be imported.
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/vec3_ops.hpp"
#include "geom/sizing/element_budget.hpp"
#include "geom/import/import.hpp"
#include "geom/prepare.hpp"
#include "geom/sizing/sizing.hpp"
#include "geom/model/surface_map_occt.hpp"
#include "geom/tubes/tubes.hpp"
#include "geom/working_scale.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/option_checks.hpp"

namespace tubemesh::cli {

namespace {

struct InspectArgs {
    std::string path;
    bool json = false;
    double size = 0;
    double sweep_size = 0;
    int solid = 0;
};

// JSON has no infinity: "no such distance" (one tube, a straight tube) is null.
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

std::string text_number(double x) { return std::isfinite(x) ? fmt::format("{:.6g}", x) : "none"; }

std::string join(const std::vector<int>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size(); ++i) s += (i ? "," : "") + std::to_string(ids[i]);
    return s;
}

// "wall of tube 2", "host of tube 1 (E1)", or "" for an ordinary boundary face.
std::map<int, std::string> face_roles(const geom::TubeSearch& found) {
    std::map<int, std::string> roles;
    for (std::size_t t = 0; t < found.tubes.size(); ++t) {
        const geom::TubeInfo& tube = found.tubes[t];
        const std::string name = "tube " + std::to_string(t + 1);
        for (int f : tube.faces) roles[f] = "wall of " + name;
        for (int k = 0; k < 2; ++k) {
            std::string& role = roles[tube.hosts[k]];
            role += (role.empty() ? "" : "; ") + ("host of " + name + (k == 0 ? " (E1)" : " (E2)"));
        }
    }
    return roles;
}

nlohmann::json tube_json(const geom::TubeInfo& t, int id) {
    return {{"id", id},
            {"faces", t.faces},
            {"hosts", t.hosts},
            {"loop_edges", t.loops},
            {"loop_lengths", t.loop_lengths},
            {"radius_min", t.radius_min},
            {"radius_max", t.radius_max},
            {"length", t.length},
            {"min_curvature_radius", number(t.min_curvature_radius)},
            {"max_kink_deg", t.max_kink_deg}};
}

nlohmann::json plan_json(const geom::SizePlan& p) {
    nlohmann::json changes = nlohmann::json::array();
    for (const geom::SizeChange& c : p.changes)
        changes.push_back({{"rule", c.rule},
                           {"old_St", c.old_sweep_size},
                           {"new_St", c.new_sweep_size},
                           {"old_S", c.old_size},
                           {"new_S", c.new_size},
                           {"reason", c.reason}});
    return {{"S", p.size},        {"initial_S", p.initial_size}, {"initial_St", p.initial_sweep_size},
            {"St", p.sweep_size}, {"S_source", p.size_source},   {"St_source", p.sweep_source},
            {"Dc", number(p.dc)}, {"Dcb", number(p.dcb)},        {"Rc", number(p.rc)},
            {"changes", changes}, {"warnings", p.warnings}};
}

// The element bound at the planned sizes and the limit `tubemesh mesh` checks it against.
struct Bound {
    geom::ElementEstimate estimate;
    double limit = 0;
    std::string limit_text;  // where the limit comes from: the memory this process may use
    bool refused() const { return geom::exceeds_limit(estimate, limit); }
};

nlohmann::json bound_json(const Bound& b) {
    return {{"tets", b.estimate.tets},         {"triangles", b.estimate.triangles},
            {"hexes", b.estimate.hexes},       {"pyramids", b.estimate.pyramids},
            {"quads", b.estimate.quads},       {"total", b.estimate.total()},
            {"limit", number(b.limit)},        {"limit_source", b.limit_text},
            {"refused", b.refused()}};
}

// The model's volume and box in the file's unit (the model is at working scale).
double source_volume(const geom::Model& model) {
    const int k = model.scale_exponent();
    return geom::from_working(geom::from_working(geom::from_working(model.volume(), k), k), k);
}

geom::BoundingBox source_bounds(const geom::Model& model) {
    const int k = model.scale_exponent();
    const geom::BoundingBox b = model.bounds();
    const auto back = [k](const Vec3& p) {
        return Vec3{geom::from_working(p.x, k), geom::from_working(p.y, k), geom::from_working(p.z, k)};
    };
    return {back(b.min), back(b.max)};
}

nlohmann::json inspect_json(const geom::Model& model, const std::vector<int>& loops_per_face,
                            const geom::TubeSearch& found, const geom::SizePlan& plan, const Bound& bound) {
    const auto roles = face_roles(found);
    nlohmann::json faces = nlohmann::json::array();
    for (int f = 1; f <= model.face_count(); ++f) {
        const auto it = roles.find(f);
        faces.push_back({{"id", f}, {"loops", loops_per_face[f - 1]}, {"role", it == roles.end() ? "" : it->second}});
    }
    nlohmann::json tubes = nlohmann::json::array();
    for (std::size_t t = 0; t < found.tubes.size(); ++t)
        tubes.push_back(tube_json(found.tubes[t], static_cast<int>(t + 1)));
    nlohmann::json rejected = nlohmann::json::array();
    for (const geom::TubeRejection& r : found.rejected) rejected.push_back({{"faces", r.faces}, {"reason", r.reason}});
    const geom::ImportReport& report = model.report();
    return {{"file", report.source}, {"format", report.format},     {"length_unit", report.length_unit},
            {"faces", faces},        {"edges", model.edge_count()}, {"volume", source_volume(model)},
            {"tubes", tubes},        {"not_tubes", rejected},       {"sizes", plan_json(plan)},
            {"elements_at_least", bound_json(bound)}, {"working_scale_exponent", model.scale_exponent()}};
}

void print_text(const geom::Model& model, const std::vector<int>& loops_per_face, const geom::TubeSearch& found,
                const geom::SizePlan& plan, const Bound& bound) {
    const geom::ImportReport& report = model.report();
    geom::BoundingBox b = source_bounds(model);
    // A side 1e-12 of the box or less from 0 is a plane through 0 (a vertex at -5e-17): print 0.
    const double size = norm(b.max - b.min);
    for (double* v : {&b.min.x, &b.min.y, &b.min.z, &b.max.x, &b.max.y, &b.max.z})
        if (std::abs(*v) <= 1e-12 * size) *v = 0;
    fmt::print("{} ({}, {}): {} faces, {} edges, volume {:.6g}\n", report.source, report.format, report.length_unit,
               model.face_count(), model.edge_count(), source_volume(model));
    fmt::print("bounding box ({:.6g}, {:.6g}, {:.6g}) to ({:.6g}, {:.6g}, {:.6g})\n\n", b.min.x, b.min.y, b.min.z,
               b.max.x, b.max.y, b.max.z);

    const auto roles = face_roles(found);
    fmt::print("faces:\n");
    for (int f = 1; f <= model.face_count(); ++f) {
        const auto it = roles.find(f);
        fmt::print("  {:>12}  {} loop{}{}\n", geom::Model::face_name(f), loops_per_face[f - 1],
                   loops_per_face[f - 1] == 1 ? "" : "s", it == roles.end() ? "" : "  " + it->second);
    }

    fmt::print("\n{} tube{}:\n", found.tubes.size(), found.tubes.size() == 1 ? "" : "s");
    for (std::size_t t = 0; t < found.tubes.size(); ++t) {
        const geom::TubeInfo& tube = found.tubes[t];
        const std::string radius = std::abs(tube.radius_max - tube.radius_min) <= 1e-6 * tube.radius_max
                                       ? fmt::format("{:.6g}", tube.radius_max)
                                       : fmt::format("{:.6g} to {:.6g}", tube.radius_min, tube.radius_max);
        fmt::print("  tube {}: faces {}, radius {}, length {:.6g}, bend radius {}, hosts face_{} and face_{}\n", t + 1,
                   join(tube.faces), radius, tube.length, text_number(tube.min_curvature_radius), tube.hosts[0],
                   tube.hosts[1]);
        if (tube.max_kink_deg > 0.5)
            fmt::print("          kinks of up to {:.3g} degrees between faces\n", tube.max_kink_deg);
    }
    if (!found.rejected.empty()) {
        fmt::print("\nnot tubes:\n");
        for (const geom::TubeRejection& r : found.rejected)
            fmt::print("  {}{}\n", r.faces.empty() ? "" : "faces " + join(r.faces) + ": ", r.reason);
    }

    fmt::print("\nsizes: S = {:.6g}, St = {:.6g}\n", plan.size, plan.sweep_size);
    fmt::print("  from S = {:.6g} ({}), St = {:.6g} ({})\n", plan.initial_size, plan.size_source,
               plan.initial_sweep_size, plan.sweep_source);
    fmt::print("  Dc = {}, Dcb = {}, Rc = {}\n", text_number(plan.dc), text_number(plan.dcb), text_number(plan.rc));
    for (const geom::SizeChange& c : plan.changes)
        fmt::print("  {}: St {:.6g} -> {:.6g}, S {:.6g} -> {:.6g}: {}\n", c.rule, c.old_sweep_size, c.new_sweep_size,
                   c.old_size, c.new_size, c.reason);
    for (const std::string& w : plan.warnings) fmt::print("  warning: {}\n", w);
    if (model.scale_exponent() != 0) fmt::print("  {}\n", geom::working_scale_line(model.scale_exponent()));

    const geom::ElementEstimate& e = bound.estimate;
    fmt::print("\nelements at these sizes: at least {:.3g} (tets {:.3g}, surface triangles {:.3g}, hexes {:.3g}, "
               "pyramids {:.3g}, ring quads {:.3g})\nlimit: {}{}\n",
               e.total(), e.tets, e.triangles, e.hexes, e.pyramids, e.quads, bound.limit_text,
               bound.refused() ? "; `tubemesh mesh` refuses these sizes" : "");
}

}  // namespace

Command add_inspect_command(CLI::App& app) {
    auto args = std::make_shared<InspectArgs>();
    CLI::App* cmd = app.add_subcommand("inspect", "Show the faces, tubes and mesh sizes tubemesh finds in a CAD file");
    cmd->add_option("FILE", args->path, "CAD file (STEP, IGES or BREP)")->required();
    cmd->add_flag("--json", args->json, "Print one JSON object (with a `tubes` array) instead of text");
    cmd->add_option("--size", args->size, "Overall mesh size S (default: bounding-box diagonal / 25)")
        ->check(positive_number());
    cmd->add_option("--sweep-size", args->sweep_size, "Hex ring thickness St (default: smallest tube diameter)")
        ->check(positive_number());
    cmd->add_option("--solid", args->solid, "Which solid of the file, 1-based (when it holds several)")
        ->check(whole_number(1, 1 << 30));
    cmd->footer("Exit status: 0 inspected, 2 the file cannot be imported.");
    return {cmd, [args]() -> int {
                geom::ImportOptions import;
                import.solid = args->solid;
                const geom::Model model = geom::import_model(args->path, import);  // Error -> exit 2 in main
                const int k = model.scale_exponent();
                const geom::TubeSearch found = geom::find_tubes(model);
                geom::SizingOptions sizing;
                sizing.size = geom::to_working(args->size, k);
                sizing.sweep_size = geom::to_working(args->sweep_size, k);
                const geom::SizePlan plan = geom::plan_sizes(model, found.tubes, sizing);
                std::vector<int> loops;
                for (const auto& map : geom::make_surface_maps(model))
                    loops.push_back(static_cast<int>(map->trimming_loops(0).size()));
                // The same bound and limit `tubemesh mesh` checks (default options).
                const geom::PrepareOptions prepare;
                const Bound bound{geom::estimate_run_elements(model, found, plan, prepare),
                                  geom::element_limit(prepare.budget), geom::element_limit_text(prepare.budget)};
                // Every figure shown in the file's unit (the model is at working scale).
                const geom::TubeSearch found_shown = geom::at_source_scale(found, k);
                const geom::SizePlan plan_shown = geom::at_source_scale(plan, k);
                if (args->json)
                    fmt::print("{}\n", inspect_json(model, loops, found_shown, plan_shown, bound).dump(2));
                else
                    print_text(model, loops, found_shown, plan_shown, bound);
                return 0;
            }};
}

}  // namespace tubemesh::cli
