#pragma once
// Random blocks with pipes deliberately close to each other and to a face, for the mesher's
// diagnosis and thin rings: what the random blocks (random_block.hpp) are built never to be.
#include <cstdint>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

// A box with sides 3 to 6 and two straight pipes of diameters 0.1 to 0.3. Pipe 1 runs along x
// at a gap g1 above the bottom face; pipe 2 runs parallel to it or across it (along y) at a gap
// g2 from pipe 1. Each gap is 0 (tangent, touching) one time in ten, negative (crossing; pipe 2
// only) one time in ten, else r 10^u with u uniform in [-3, 0.5]. Clearance checks are off.
// The same block for the same seed on every machine.
BlockSpec close_block_spec(std::uint64_t seed);

}  // namespace tubemesh::geom
