#pragma once
// Fixtures and checks shared by the tet-step tests on TetDomains (engine/tets/tet_domain.hpp).
#include <vector>

#include "engine/core/types.hpp"
#include "engine/tets/tet_domain.hpp"

namespace tubemesh::testing {

// A closed front: the grid-triangulated surface of the cube [lo,hi]^3, n cells per edge,
// normals outward (or inward, for a hole), appended to xyz / front (3 ids per triangle).
// Points shared between faces are merged.
void cube_front(double lo, double hi, int n, bool outward, std::vector<double>& xyz, std::vector<index_t>& front);

// gtest checks of the domain's invariants: positive tets (exact orient3d), symmetric adjacency
// across the same three points, the boundary faces exactly `front`, every free point in a tet.
void expect_valid(const tets::TetDomain& d, const std::vector<index_t>& front);

}  // namespace tubemesh::testing
