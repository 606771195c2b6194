// Output format by file extension (case-insensitive): the CLI's one way to write a mesh.
#include <algorithm>
#include <cctype>
#include <string>

#include "engine/io/mesh_io.hpp"

namespace tubemesh {

void write_mesh(const HybridMesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".msh")
        write_msh(mesh, path, options.msh_encoding, options.description);
    else if (ext == ".vtu")
        write_vtu(mesh, path, options.description);
    else if (ext == ".vtm")
        write_vtm(mesh, path, options.description);
    else if (ext == ".inp")
        write_inp(mesh, path, options);
    else
        throw Error("cannot write '" + path.string() + "': " +
                    (ext.empty() ? std::string("the file name has no extension")
                                 : "unknown mesh format '" + ext + "'") +
                    "; use .msh (Gmsh), .vtu or .vtm (ParaView) or .inp (Abaqus, CalculiX)");
}

}  // namespace tubemesh
