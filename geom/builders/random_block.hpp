#pragma once
// Random blocks for sweeps and fuzzing: a box with 1 to 12 smooth curved pipes, the same block
// for the same seed on every machine.
#include <cstdint>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

// Box sides 4 to 10; pipe diameters 0.035 to 0.2. Each pipe is a cubic B-spline that enters and
// leaves through faces (possibly the same face: a U-bend), meets them within 20 degrees of square
// and at least 0.6 + 4 diameters from their edges, bends no tighter than 4 diameters, keeps 3
// diameters from every other pipe and 2 from the faces away from its ends. Pipes that cannot be
// placed after a number of tries are left out, so a block may hold fewer than it drew; never none.
BlockSpec random_block_spec(std::uint64_t seed);

}  // namespace tubemesh::geom
