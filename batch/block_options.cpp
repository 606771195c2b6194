#include "batch/block_options.hpp"

#include <fmt/format.h>

#include <iostream>

#include "batch/sha256.hpp"
#include "engine/core/types.hpp"
#include "job/option_table.hpp"
#include "job/outputs.hpp"

namespace tubemesh::batch {

namespace {

using json = nlohmann::json;

bool in_manifest(const job::OptionSpec& s) { return s.shown & job::kManifest; }

}  // namespace

json default_block_options() {
    json out = json::object();
    for (const job::OptionSpec& s : job::option_table())
        if (in_manifest(s)) out[s.key] = s.fallback;
    return out;
}

json manifest_schema() {
    json out = json::object();
    for (const job::OptionSpec& s : job::option_table()) {
        if (!in_manifest(s)) continue;
        json entry = {{"default", s.fallback}, {"help", s.help}, {"default_text", s.default_text}};
        if (!s.units.empty()) entry["units"] = s.units;
        if (!s.choices.empty()) entry["choices"] = s.choices;
        if (s.type == job::OptionType::Number || s.type == job::OptionType::Whole) entry["range"] = {s.lo, s.hi};
        for (const job::OptionAlias& a : s.aliases)
            if (a.shown & job::kManifest) entry["deprecated_names"].push_back(a.name);
        out[s.key] = entry;
    }
    return out;
}

json merge_block_options(const json& base, const json& overrides, const std::string& where) {
    if (overrides.is_null()) return base;
    if (!overrides.is_object()) throw Error(where + ": options must be an object");
    json out = base;
    const json given = job::canonical_options(overrides, job::kManifest, where, [&](const std::string& message) {
        std::cerr << "tubemesh: warning: " << where << ": " << message << "\n";
    });
    for (const auto& [key, value] : given.items()) out[key] = value;
    if (out.at("time_limit").get<double>() < 0)
        throw Error(fmt::format("{}: \"time_limit\" must be at least 0 (0: none), got {}", where, out["time_limit"].dump()));
    try {
        job::JobSettings s = settings_of(out);
        std::vector<std::string> outputs = block_outputs(out);
        job::job_write_options(s, outputs, job::Naming::Keywords);
    } catch (const Error& e) {
        throw Error(where + ": " + e.what());
    }
    return out;
}

std::string options_hash(const json& options) {
    // The names and options the hash has always had: an option added since enters only away from
    // its default, under its first name, so a block's hash (and its mesh) stays what it was.
    json keyed = json::object();
    for (const job::OptionSpec& s : job::option_table()) {
        if (!in_manifest(s) || s.hashed == job::Hashed::Never || !options.contains(s.key)) continue;
        json value = options.at(s.key);
        if (s.hashed == job::Hashed::WhenChanged && value == s.fallback) continue;
        std::string name = s.key;
        for (const job::OptionAlias& a : s.aliases)
            if (s.hash_name == a.name) {
                name = a.name;
                value = job::value_from_alias({&s, &a}, value);
            }
        // Numbers as doubles, so 1 and 1.0 hash alike.
        keyed[name] = value.is_number() ? json(value.get<double>()) : value;
    }
    keyed["tubemesh"] = TUBEMESH_VERSION;
    return sha256_hex(keyed.dump());
}

job::JobSettings settings_of(const json& options) {
    // The options away from their defaults are the ones given (economy sets what is not given).
    json given = json::object();
    for (const auto& [key, value] : options.items())
        if (const job::OptionSpec* s = job::find_option(key); s && value != s->fallback) given[key] = value;
    return job::job_settings(given, job::Naming::Keywords);
}

std::vector<std::string> block_outputs(const json& options) {
    std::vector<std::string> outputs;
    for (const json& f : options.at("formats"))
        if (f != "html") outputs.push_back("block." + f.get<std::string>());
    return outputs;
}

MeshOptions mesh_options(const json& o, int threads) {
    job::JobSettings s = settings_of(o);
    s.mesh.threads = threads;
    return job::mesh_options(s.mesh, job::Naming::Keywords);
}

int solid_of(const json& o) { return o.at("solid").is_null() ? 0 : o.at("solid").get<int>(); }

}  // namespace tubemesh::batch
