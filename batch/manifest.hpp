#pragma once
// The batch manifest: which blocks to mesh and with which options. JSON:
//
//   {
//     "tubemesh_batch": 1,                          format version, required
//     "name": "dam seed 1",                         optional
//     "defaults": {"size": 0.8, "formats": ["msh", "vtu"]},   optional, over the built-ins
//     "blocks": [
//       {"id": "c1-l1", "cad": "c1-l1.step"},                  a CAD file (.step .iges .brep)
//       {"id": "c1-l2", "spec": "c1-l2.json", "options": {"size": 0.6}},   a builder spec file
//       {"id": "test", "spec": {"box": [4, 3, 2], "pipes": []}},           or the spec inline
//       ...
//     ]
//   }
//
// Paths are relative to the manifest's folder. An id names the block's files in the output
// folder (`<id>.msh`, `<id>.report.json`): letters, digits, '.', '_' and '-', unique. A block
// may carry "info" (any JSON, ignored: make-dam puts its column, lift and origin there).
// Options and their defaults: batch/block_options.hpp. Builder specs:
// geom/builders/spec_json.hpp.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace tubemesh::batch {

struct BlockEntry {
    std::string id;
    int position = 0;                 // in the manifest, from 0
    std::filesystem::path cad;        // absolute; empty for a spec
    std::string spec_text;            // the builder spec's JSON text; empty for a CAD file
    std::string spec_source;          // the spec file, or "<manifest>: block <id>" when inline
    nlohmann::json options;           // resolved (block_options.hpp)
    std::string input_hash;           // SHA-256 of the CAD file's or the spec's bytes
    std::string options_hash;
};

struct Manifest {
    std::filesystem::path path;
    std::string name;
    std::vector<BlockEntry> blocks;
};

// Reads and checks the manifest and hashes every block's input. `overrides` (the command
// line's --formats and --time-limit) go over every block's options. Throws tubemesh::Error
// naming the file and the place for a malformed manifest: the command then exits 2. A
// block's missing or unreadable input is not an error here: its hash says so and the block
// fails when it is meshed.
Manifest read_manifest(const std::filesystem::path& path, const nlohmann::json& overrides = nullptr);

// The same from the manifest's text; `path` names it in messages and anchors relative paths.
Manifest parse_manifest(const std::string& text, const std::filesystem::path& path,
                        const nlohmann::json& overrides = nullptr);

}  // namespace tubemesh::batch
