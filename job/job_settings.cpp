#include "job/job_settings.hpp"

#include "job/option_table.hpp"
#include "job/outputs.hpp"

namespace tubemesh::job {

namespace {

using json = nlohmann::json;

struct Given {
    const json& values;
    bool has(const char* key) const { return values.contains(key) && !values.at(key).is_null(); }
    // The value given, else the table's default.
    json at(const char* key) const {
        if (has(key)) return values.at(key);
        const OptionSpec* spec = find_option(key);
        if (!spec) throw Error(std::string("no option \"") + key + "\" in the option table");
        return spec->fallback;
    }
    template <class V>
    std::optional<V> optional(const char* key) const {
        const json v = at(key);
        return v.is_null() ? std::nullopt : std::optional<V>(v.get<V>());
    }
    template <class V>
    V value(const char* key) const {
        return at(key).get<V>();
    }
};

// Whole numbers arrive as doubles from some front ends (JSON 2.0, Python 2.0 is refused before).
int whole(const json& v) { return static_cast<int>(v.get<double>()); }

}  // namespace

JobSettings job_settings(const json& given_values, Naming naming) {
    const Given g{given_values};
    JobSettings j;
    MeshSettings& s = j.mesh;
    s.size = g.optional<double>("size");
    s.sweep_size = g.optional<double>("sweep_size");
    if (g.has("circ")) s.circumferential = whole(g.at("circ"));
    s.layers = whole(g.at("layers"));
    s.axial_aspect = g.value<double>("axial_aspect");
    s.chordal = g.value<double>("chordal");
    s.chordal_given = g.has("chordal");
    s.pyramid_height = g.value<double>("pyramid_height");
    s.gradation = g.value<double>("gradation");
    if (g.has("threads")) s.threads = whole(g.at("threads"));
    s.tet_parts = whole(g.at("tet_parts"));
    s.tet_relax = whole(g.at("tet_relax"));
    s.move_apexes = g.value<bool>("move_apexes");
    s.scale_free = g.value<bool>("scale_free");
    s.slide_surface = !g.value<bool>("fixed_surface");
    s.max_elements = g.optional<double>("max_elements");
    if (g.has("solid")) s.solid = whole(g.at("solid"));
    if (g.value<bool>("economy"))
        apply_economy(s, {.layers = g.has("layers"), .axial_aspect = g.has("axial_aspect"), .chordal = g.has("chordal")});
    // The economy's one St unless the user said which ring.
    if (g.has("global_ring") || !g.value<bool>("economy")) s.local_ring = !g.value<bool>("global_ring");
    s.until = g.has("until") ? stage_named(g.value<std::string>("until"), naming) : kLastStage;

    j.assembly = g.value<bool>("assembly");
    j.glue_tolerance = g.optional<double>("glue_tolerance").value_or(0);
    if (j.glue_tolerance < 0 || (g.has("glue_tolerance") && !(j.glue_tolerance > 0)))
        throw Error(option_name("glue_tolerance", naming) + " must be a positive number");
    j.outputs = g.value<std::vector<std::string>>("output");
    j.report = g.value<std::string>("report");
    j.html = g.value<std::string>("html");
    j.msh_ascii = g.value<bool>("msh_ascii");
    j.inp_family = g.value<std::string>("inp_family");
    j.inp_pyramid = g.value<std::string>("inp_pyramid");
    j.pipe_network = g.value<bool>("pipe_network");
    if (g.has("film_coefficient")) j.film_coefficient = g.value<double>("film_coefficient");
    for (const json& k : g.at("reverse_flow")) j.reverse_flow.push_back(whole(k));
    j.quiet = g.value<bool>("quiet");
    mesh_options(s, naming);  // the ranges, before any work
    return j;
}

json canonical_options(const json& named, unsigned where, const std::string& context,
                       const std::function<void(const std::string&)>& warn) {
    json out = json::object();
    for (const auto& [name, value] : named.items()) {
        const NamedOption o = option_named(name, static_cast<Shown>(where));
        if (!o.spec) throw Error(context + ": unknown option \"" + name + "\"");
        check_option_type(*o.spec, name, value, context);
        if (o.alias) warn(deprecation_message(o, static_cast<Shown>(where)));
        out[o.spec->key] = value_from_alias(o, value);
    }
    return out;
}

WriteOptions job_write_options(const JobSettings& j, std::vector<std::string>& files, Naming naming) {
    WriteOptions w = write_options(j.msh_ascii, j.inp_family, j.inp_pyramid, naming);
    w.pipe_network = pipe_network_options(j.pipe_network, j.film_coefficient, j.reverse_flow, files, naming);
    return w;
}

}  // namespace tubemesh::job
