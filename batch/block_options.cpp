#include "batch/block_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "batch/sha256.hpp"
#include "engine/core/types.hpp"
#include "job/mesh_settings.hpp"
#include "job/outputs.hpp"

namespace tubemesh::batch {

namespace {

struct Key {
    const char* name;
    bool whole;     // a whole number
    bool nullable;  // null: automatic
};
constexpr Key kNumbers[] = {{"size", false, true},          {"sweep_size", false, true},   {"circ", true, true},
                            {"layers", true, false},        {"axial_aspect", false, false}, {"chordal", false, false},
                            {"pyramid_height", false, false}, {"gradation", false, false}, {"tet_parts", true, false},
                            {"tet_relax", true, false},     {"max_elements", false, true}, {"solid", true, true},
                            {"time_limit", false, false}, {"film_coefficient", false, false}};

void check_formats(const nlohmann::json& v, const std::string& where) {
    if (!v.is_array() || v.empty()) throw Error(where + ": \"formats\" must be a non-empty list such as [\"msh\"]");
    for (const nlohmann::json& f : v)
        if (!f.is_string() || (f != "msh" && f != "vtu" && f != "inp" && f != "html"))
            throw Error(where + ": \"formats\" takes \"msh\", \"vtu\", \"inp\" and \"html\" (the block's report), got " +
                        f.dump());
}

// Types here; ranges by job::mesh_options once the block's options are complete.
void check_value(const std::string& key, const nlohmann::json& v, const std::string& where) {
    if (key == "formats") return check_formats(v, where);
    if (key == "reverse_flow") {
        if (!v.is_array()) throw Error(fmt::format("{}: \"reverse_flow\" must be a list of pipe numbers, got {}", where, v.dump()));
        for (const nlohmann::json& k : v)
            if (!k.is_number_integer())
                throw Error(fmt::format("{}: \"reverse_flow\" takes whole pipe numbers, got {}", where, k.dump()));
        return;
    }
    if (key == "move_apexes" || key == "slide_surface" || key == "pipe_network" ||
        key == "local_ring") {
        if (!v.is_boolean()) throw Error(fmt::format("{}: \"{}\" must be true or false, got {}", where, key, v.dump()));
        return;
    }
    for (const Key& k : kNumbers) {
        if (key != k.name) continue;
        const bool automatic = v.is_null() && k.nullable;
        if (!automatic && !(v.is_number() && std::isfinite(v.get<double>())))
            throw Error(fmt::format("{}: \"{}\" must be a number{}, got {}", where, key,
                                    k.nullable ? " or null (automatic)" : "", v.dump()));
        // Whole numbers become ints: beyond that range they are out of every option's range anyway.
        if (!automatic && k.whole &&
            (v.get<double>() != std::floor(v.get<double>()) || std::abs(v.get<double>()) > 1e9))
            throw Error(fmt::format("{}: \"{}\" must be a whole number of at most 1e9, got {}", where, key, v.dump()));
        if (key == "time_limit" && v.get<double>() < 0)
            throw Error(fmt::format("{}: \"time_limit\" must be at least 0 (0: none), got {}", where, v.dump()));
        return;
    }
    throw Error(where + ": unknown option \"" + key + "\"");
}

template <class T>
std::optional<T> optional_of(const nlohmann::json& o, const char* key) {
    if (o.at(key).is_null()) return std::nullopt;
    return o.at(key).get<T>();
}

job::MeshSettings settings_of(const nlohmann::json& o) {
    job::MeshSettings s;
    s.size = optional_of<double>(o, "size");
    s.sweep_size = optional_of<double>(o, "sweep_size");
    s.circumferential = optional_of<int>(o, "circ");
    s.layers = o.at("layers").get<int>();
    s.axial_aspect = o.at("axial_aspect").get<double>();
    s.chordal = o.at("chordal").get<double>();
    s.move_apexes = o.at("move_apexes").get<bool>();
    s.slide_surface = o.at("slide_surface").get<bool>();
    s.local_ring = o.at("local_ring").get<bool>();
    s.pyramid_height = o.at("pyramid_height").get<double>();
    s.gradation = o.at("gradation").get<double>();
    s.tet_parts = o.at("tet_parts").get<int>();
    s.tet_relax = o.at("tet_relax").get<int>();
    s.max_elements = optional_of<double>(o, "max_elements");
    s.solid = optional_of<int>(o, "solid");
    return s;
}

}  // namespace

nlohmann::json default_block_options() {
    const job::MeshSettings d;
    return {{"size", nullptr},
            {"sweep_size", nullptr},
            {"circ", nullptr},
            {"layers", d.layers},
            {"axial_aspect", d.axial_aspect},
            {"chordal", d.chordal},
            {"pyramid_height", d.pyramid_height},
            {"gradation", d.gradation},
            {"tet_parts", d.tet_parts},
            {"tet_relax", d.tet_relax},
            {"move_apexes", d.move_apexes},
            {"slide_surface", d.slide_surface},
            {"local_ring", d.local_ring},
            {"max_elements", nullptr},
            {"solid", nullptr},
            {"formats", {"msh"}},
            {"pipe_network", false},
            {"film_coefficient", PipeNetworkOptions{}.film_coefficient},
            {"reverse_flow", nlohmann::json::array()},
            {"time_limit", 3600.0}};
}

nlohmann::json merge_block_options(const nlohmann::json& base, const nlohmann::json& overrides,
                                   const std::string& where) {
    if (overrides.is_null()) return base;
    if (!overrides.is_object()) throw Error(where + ": options must be an object");
    nlohmann::json out = base;
    for (const auto& [key, value] : overrides.items()) {
        check_value(key, value, where);
        out[key] = value;
    }
    try {
        job::mesh_options(settings_of(out), job::Naming::Keywords);
        pipe_network_of(out);
    } catch (const Error& e) {
        throw Error(where + ": " + e.what());
    }
    return out;
}

std::string options_hash(const nlohmann::json& options) {
    nlohmann::json keyed = options;
    keyed.erase("time_limit");
    // Numbers as doubles, so 1 and 1.0 hash alike.
    for (auto& [key, value] : keyed.items())
        if (value.is_number()) value = value.get<double>();
    keyed["tubemesh"] = TUBEMESH_VERSION;
    return sha256_hex(keyed.dump());
}

MeshOptions mesh_options(const nlohmann::json& o, int threads) {
    job::MeshSettings s = settings_of(o);
    s.threads = threads;
    return job::mesh_options(s, job::Naming::Keywords);
}

PipeNetworkOptions pipe_network_of(const nlohmann::json& o) {
    std::vector<std::string> outputs;
    for (const nlohmann::json& f : o.at("formats"))
        if (f == "inp") outputs.push_back("block.inp");
    const double h = o.at("film_coefficient").get<double>();
    return job::pipe_network_options(o.at("pipe_network").get<bool>(),
                                     h == PipeNetworkOptions{}.film_coefficient ? std::nullopt : std::optional(h),
                                     o.at("reverse_flow").get<std::vector<int>>(), outputs, job::Naming::Keywords);
}

int solid_of(const nlohmann::json& o) { return o.at("solid").is_null() ? 0 : o.at("solid").get<int>(); }

}  // namespace tubemesh::batch
