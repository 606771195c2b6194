#pragma once
// What a ring thinned by its room (TubeData::room) asks of the layers in front of it, per outer
// quad. The room leaves a gap of about 2.4 ring thicknesses ahead of a thinned ring (a ring
// and its pyramids take 3.2 St towards a face, over a 95 % margin), whatever the quad's size:
// its pyramid stands 0.6 ring thicknesses tall and the tets in front of it are sized about two
// thicknesses, the gap left between the apexes and the face.
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/sweep/sweep.hpp"

namespace tubemesh {

struct ThinRingShares {
    // Per outer quad, the share of the paper's apex height (PyramidInput::front_scale) and of
    // the quad's mean edge as the tet size (TetSizeCaps' quad_scale): 1 over a full ring. Both
    // empty when every ring has its full St.
    std::vector<double> apex, tet_size;
};

ThinRingShares thin_ring_shares(const HybridMesh& mesh, const SweepResult& sweep, double height_factor);

}  // namespace tubemesh
