#pragma once
// Fixtures and checks shared by the tet-step tests on TetDomains (engine/tets/domain/tet_domain.hpp).
#include <vector>

#include "engine/core/types.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::testing {

// A closed front: the grid-triangulated surface of the box [lo,hi] (n x n cells per face, each
// split along the diagonal from its first corner), normals outward (or inward, for a hole),
// appended to xyz / front (3 ids per triangle). Points shared between faces are merged.
void box_front(const double lo[3], const double hi[3], int n, bool outward, std::vector<double>& xyz,
               std::vector<index_t>& front);
// box_front of the cube [lo,hi]^3.
void cube_front(double lo, double hi, int n, bool outward, std::vector<double>& xyz, std::vector<index_t>& front);

// The unit cube (10 cells per edge) with the cubic hole [0.35,0.65]^3 (hole_cells per edge),
// through boundary recovery on 2 threads and 2 parts.
tets::TetDomain recovered_cube_with_hole(int hole_cells);

// gtest checks of the domain's invariants: positive tets (exact orient3d), symmetric adjacency
// across the same three points, the boundary faces exactly `front`, every free point in a tet.
void expect_valid(const tets::TetDomain& d, const std::vector<index_t>& front);

}  // namespace tubemesh::testing
