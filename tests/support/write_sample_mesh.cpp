// Writes one of the hand-made sample meshes to a file: used by tools/run.sh (until the
// meshing pipeline exists) and handy for trying `tubemesh check` by hand.
//   write_sample_mesh conforming|hex-facing-tets|flipped-pyramid OUT.msh|.vtu|.inp
#include <cstdio>
#include <exception>
#include <string>

#include "engine/io/mesh_io.hpp"
#include "tests/support/sample_meshes.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: write_sample_mesh conforming|hex-facing-tets|flipped-pyramid OUT\n");
        return 2;
    }
    const std::string which = argv[1];
    try {
        tubemesh::HybridMesh mesh;
        if (which == "conforming")
            mesh = tubemesh::testing::conforming_patch();
        else if (which == "hex-facing-tets")
            mesh = tubemesh::testing::hex_facing_two_tets();
        else if (which == "flipped-pyramid")
            mesh = tubemesh::testing::flipped_pyramid_patch();
        else {
            std::fprintf(stderr, "write_sample_mesh: unknown sample '%s'\n", which.c_str());
            return 2;
        }
        tubemesh::write_mesh(mesh, argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "write_sample_mesh: %s\n", e.what());
        return 2;
    }
    return 0;
}
