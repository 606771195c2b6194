#pragma once
// Writers check the mesh's layout before creating any file: a bad node index would otherwise
// become a corrupt file (or an out-of-bounds read) instead of an error.
#include <filesystem>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::io {

inline void check_layout_for_writing(const HybridMesh& mesh, const std::filesystem::path& path) {
    try {
        mesh.validate_layout();
    } catch (const Error& e) {
        throw Error("cannot write '" + path.string() + "': " + e.what());
    }
}

}  // namespace tubemesh::io
