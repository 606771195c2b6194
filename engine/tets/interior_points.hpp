#pragma once
// Advancing-front interior points (paper §5): ideal points proposed on the active front and
// filtered by the size field. Pure functions of the mesh state: refine.cpp inserts the result.
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/delaunay/tet_store.hpp"

namespace tubemesh::tets {

class ControlSpace;

// A proposed point: where, the size there, and the tet of the mesh that holds it.
struct Candidate {
    double p[3];
    double h;
    index_t tet;
};

// Points given by kernel-style arrays: 3 coordinates per point id.
struct MeshView {
    const delaunay::TetStore& tets;  // may hold free slots (vertex[0] == kFreeSlot)
    std::span<const double> xyz;
};

// True when the tet's mean edge length exceeds `tolerance` times h at its centroid.
bool tet_too_big(const MeshView& mesh, index_t tet, const ControlSpace& space, double tolerance);

// The active front: faces 4*t+f of too-big tets t whose other side is the front or a tet that
// is not too big (the front of the resolved region), in increasing order. Parallel.
std::vector<index_t> active_faces(const MeshView& mesh, const ControlSpace& space, double tolerance);

// One ideal point per active face: the apex of a near-regular tet of size h on the face, on
// the side of the face's tet; dropped when a walk from that tet leaves the region through the
// front. Parallel; the order follows `faces`.
std::vector<Candidate> propose_points(const MeshView& mesh, std::span<const index_t> faces,
                                      const ControlSpace& space);

// Keeps the candidates farther than `reject_factor` * h from every point in `existing`
// (3 coordinates each) and from every candidate kept before them (greedy in order, so the
// result does not depend on the thread count). Returns the kept positions in `candidates`.
std::vector<index_t> select_points(std::span<const Candidate> candidates, std::span<const double> existing,
                                   double reject_factor);

}  // namespace tubemesh::tets
