#pragma once
// Small hand-made hybrid meshes shared by the check, io and CLI tests.
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::testing {

// Unit cube hex [0,1]^3; on its top face a pyramid with apex at the centre c = (.5,.5,1.5)
// of the cube [0,1]^2 x [1,2] above; the rest of that upper cube as 10 tets (its five other
// faces each coned to c, each cone split along a base diagonal). Conforming and valid:
// 1 hex, 1 pyramid, 10 tets, 13 nodes. Boundary: 5 hex quads ("hex_sides"), 10 triangles
// ("upper_sides"). Regions "hex_ring", "pyramids", "tets".
HybridMesh conforming_patch();

// The hex with the upper cube split into 6 tets straight on its top quad: the hex quad faces
// two tet triangles (no pyramid). Every cell is valid.
HybridMesh hex_facing_two_tets();

// conforming_patch() with the pyramid's base order reversed: its base matches the hex quad
// with the same orientation and its volume is negative.
HybridMesh flipped_pyramid_patch();

}  // namespace tubemesh::testing
