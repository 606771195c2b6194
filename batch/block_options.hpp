#pragma once
// A block's options as the manifest spells them, resolved over the built-in defaults: the option
// table's manifest keys (job/option_table.hpp; README's option table lists them), with the same
// meaning, defaults and ranges as `tubemesh mesh`'s flags and the Python keywords. null is
// automatic, as when left out. Everything but time_limit goes into the options hash: a block
// whose options change is meshed again.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/pipeline/pipeline.hpp"
#include "job/job_settings.hpp"

namespace tubemesh::batch {

// Every key with its default value (null where automatic).
nlohmann::json default_block_options();

// Every key with its default, help, units, range and choices: what a manifest may hold.
nlohmann::json manifest_schema();

// `base` with the keys of `overrides` replaced (older spellings warned about on stderr and
// turned into their key). Throws tubemesh::Error naming `where` and the key for an unknown key,
// a value of the wrong type or one out of range.
nlohmann::json merge_block_options(const nlohmann::json& base, const nlohmann::json& overrides,
                                   const std::string& where);

// The options that decide the mesh's bytes, with the program's version: what the options
// hash is taken of.
std::string options_hash(const nlohmann::json& options);

// The job's settings for resolved block options: the options away from their defaults count as
// given. No files: the worker names them.
job::JobSettings settings_of(const nlohmann::json& options);

// The block's mesh files by format, named "block.<format>" (for the checks made on the manifest).
std::vector<std::string> block_outputs(const nlohmann::json& options);

// The engine's options for resolved block options, on `threads` threads.
MeshOptions mesh_options(const nlohmann::json& options, int threads);

// Which solid of the block's file, 1-based; 0: the file holds one.
int solid_of(const nlohmann::json& options);

}  // namespace tubemesh::batch
