#include "batch/manifest.hpp"

#include <regex>
#include <set>

#include "batch/block_options.hpp"
#include "batch/sha256.hpp"
#include "engine/core/types.hpp"
#include "engine/io/file_bytes.hpp"

namespace tubemesh::batch {

namespace {

namespace fs = std::filesystem;

void only_keys(const nlohmann::json& o, std::initializer_list<const char*> keys, const std::string& where) {
    for (const auto& item : o.items()) {
        bool known = false;
        for (const char* k : keys) known = known || item.key() == k;
        if (!known) throw Error(where + ": unknown key \"" + item.key() + "\"");
    }
}

// The file's hash, or a hash that says it could not be read (the block then fails alone).
std::string file_hash(const fs::path& path) {
    try {
        return sha256_file(path);
    } catch (const Error&) {
        return sha256_hex("unreadable: " + path.string());
    }
}

BlockEntry read_block(const nlohmann::json& b, int position, const fs::path& folder, const nlohmann::json& defaults,
                      const nlohmann::json& overrides, const std::string& file) {
    const std::string at = file + ": block " + std::to_string(position + 1);
    if (!b.is_object()) throw Error(at + ": must be an object");
    only_keys(b, {"id", "cad", "spec", "options", "info"}, at);
    BlockEntry e;
    e.position = position;
    if (!b.contains("id") || !b["id"].is_string()) throw Error(at + ": needs an \"id\" string");
    e.id = b["id"].get<std::string>();
    static const std::regex kId("[A-Za-z0-9][A-Za-z0-9._-]*");
    if (!std::regex_match(e.id, kId) || e.id.size() > 200)
        throw Error(at + ": id \"" + e.id + "\" must be letters, digits, '.', '_' and '-' (it names files)");
    const std::string where = file + ": block \"" + e.id + "\"";
    if (b.contains("cad") == b.contains("spec")) throw Error(where + ": needs exactly one of \"cad\" and \"spec\"");
    if (b.contains("cad")) {
        if (!b["cad"].is_string()) throw Error(where + ": \"cad\" must be a file name");
        e.cad = fs::absolute(folder / b["cad"].get<std::string>()).lexically_normal();
        e.input_hash = file_hash(e.cad);
    } else if (b["spec"].is_string()) {
        const fs::path spec = fs::absolute(folder / b["spec"].get<std::string>()).lexically_normal();
        e.spec_source = spec.string();
        try {
            e.spec_text = io::read_file_bytes(spec);
        } catch (const Error&) {
            e.spec_text.clear();  // the worker reports the missing file as this block's failure
        }
        e.input_hash = e.spec_text.empty() ? file_hash(spec) : sha256_hex(e.spec_text);
    } else if (b["spec"].is_object()) {
        e.spec_text = b["spec"].dump();
        e.spec_source = file + ": block " + e.id;
        e.input_hash = sha256_hex(e.spec_text);
    } else {
        throw Error(where + ": \"spec\" must be a file name or a spec object");
    }
    e.options = merge_block_options(defaults, b.contains("options") ? b["options"] : nlohmann::json(), where);
    e.options = merge_block_options(e.options, overrides, "the command line");
    e.options_hash = options_hash(e.options);
    return e;
}

}  // namespace

Manifest read_manifest(const fs::path& path, const nlohmann::json& overrides) {
    return parse_manifest(io::read_file_bytes(path), path, overrides);
}

Manifest parse_manifest(const std::string& text, const fs::path& path, const nlohmann::json& overrides) {
    const std::string file = path.string();
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for 1e99999
        throw Error("manifest '" + file + "' is not valid JSON: " + e.what());
    }
    if (!j.is_object()) throw Error("manifest '" + file + "' must hold a JSON object");
    only_keys(j, {"tubemesh_batch", "name", "defaults", "blocks"}, file);
    if (!j.contains("tubemesh_batch") || j["tubemesh_batch"] != 1)
        throw Error(file + ": not a tubemesh batch manifest (needs \"tubemesh_batch\": 1)");
    if (!j.contains("blocks") || !j["blocks"].is_array() || j["blocks"].empty())
        throw Error(file + ": needs a non-empty \"blocks\" list");

    Manifest m;
    m.path = fs::absolute(path);
    if (j.contains("name") && !j["name"].is_string()) throw Error(file + ": \"name\" must be a string");
    m.name = j.value("name", path.stem().string());
    const nlohmann::json defaults =
        merge_block_options(default_block_options(), j.contains("defaults") ? j["defaults"] : nlohmann::json(),
                            file + ": defaults");
    const fs::path folder = m.path.parent_path();
    std::set<std::string> ids;
    for (std::size_t i = 0; i < j["blocks"].size(); ++i) {
        BlockEntry e = read_block(j["blocks"][i], static_cast<int>(i), folder, defaults, overrides, file);
        if (!ids.insert(e.id).second) throw Error(file + ": block id \"" + e.id + "\" appears twice");
        m.blocks.push_back(std::move(e));
    }
    return m;
}

}  // namespace tubemesh::batch
