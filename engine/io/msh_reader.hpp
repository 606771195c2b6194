#pragma once
// The MSH reader on bytes in memory: read_msh() reads the file and calls this; the fuzz tests
// call it directly with corrupted bytes.
#include <string>
#include <string_view>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::io {

// `name` (normally the path) prefixes every error message.
HybridMesh read_msh_bytes(std::string_view bytes, const std::string& name);

}  // namespace tubemesh::io
