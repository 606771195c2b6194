#pragma once
// A block's meshing options as the manifest spells them, resolved over the built-in defaults:
//
//   size S, sweep_size St, circ n, layers L, axial_aspect, chordal, pyramid_height, gradation,
//   tet_parts, tet_relax, move_apexes, slide_surface and local_ring (true or false), max_elements, solid K
//   (null: automatic, as when left out),
//   formats ["msh", "vtu", "inp", "html" (the block's HTML report)], time_limit (seconds per block; 0: none),
//   pipe_network (true or false), film_coefficient, reverse_flow [pipe numbers] (the .inp's water
//   networks, as `tubemesh mesh --pipe-network`)
//
// The meshing options are job::MeshSettings (job/mesh_settings.hpp) under the Python
// module's keywords: the same meaning, defaults and ranges as `tubemesh mesh`'s flags.
// Everything but time_limit goes into the options hash: a block whose options change is meshed
// again.
#include <nlohmann/json.hpp>
#include <string>

#include "engine/io/mesh_io.hpp"
#include "engine/pipeline/pipeline.hpp"

namespace tubemesh::batch {

// Every key with its default value (null where automatic); formats ["msh"], time_limit 3600.
nlohmann::json default_block_options();

// `base` with the keys of `overrides` replaced. Throws tubemesh::Error naming `where` and the
// key for an unknown key, a value of the wrong type or one out of range.
nlohmann::json merge_block_options(const nlohmann::json& base, const nlohmann::json& overrides,
                                   const std::string& where);

// The options that decide the mesh's bytes, with the program's version: what the options
// hash is taken of.
std::string options_hash(const nlohmann::json& options);

// The engine's options for resolved block options, on `threads` threads.
MeshOptions mesh_options(const nlohmann::json& options, int threads);

// The water networks for the block's .inp (engine/io/inp_network.hpp).
PipeNetworkOptions pipe_network_of(const nlohmann::json& options);

// Which solid of the block's file, 1-based; 0: the file holds one.
int solid_of(const nlohmann::json& options);

}  // namespace tubemesh::batch
