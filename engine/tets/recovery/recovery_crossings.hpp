#pragma once
// Which mesh elements cross a missing front segment or triangle (the recovery "target"),
// decided with the exact predicates. A crossing is transversal and through relative
// interiors: an element that shares a vertex with the target, or only touches it, does not
// block it.
#include <vector>

#include "engine/core/types.hpp"
#include "engine/tets/recovery/recovery_mesh.hpp"

namespace tubemesh::tets {

// A missing front edge ab (c == kNoIndex) or front triangle abc.
struct Target {
    index_t a = kNoIndex, b = kNoIndex, c = kNoIndex;
    bool is_edge() const { return c == kNoIndex; }
    bool has(index_t v) const { return v == a || v == b || v == c; }
};

// Coplanar segments pq and ab whose relative interiors cross in one point.
bool segments_cross(const double* p, const double* q, const double* a, const double* b);

// Edge uv crosses the target (a segment: in one interior point; a triangle: through its interior).
bool edge_crosses(const RecoveryMesh& m, const Target& g, index_t u, index_t v);
// Triangle xyz is crossed through its interior by the target segment (always false for a
// triangle target: two faces of a mesh meet only where an edge crosses).
bool face_crossed(const RecoveryMesh& m, const Target& g, index_t x, index_t y, index_t z);
// Point w lies in the relative interior of the target segment, or of the target triangle.
bool point_on_target(const RecoveryMesh& m, const Target& g, index_t w);
bool point_on_target(const RecoveryMesh& m, const Target& g, const double* p);

struct Crossings {
    std::vector<std::pair<index_t, int>> faces;         // (tet, local face), once per face
    std::vector<std::pair<index_t, index_t>> edges;     // (u, v), u < v
    index_t vertex_on_target = kNoIndex;                 // a mesh vertex inside the target
};

// Every face and edge of the mesh crossing the target, found from the tets around the target's
// vertices outwards through crossed elements (cost: the tets the target passes through).
void find_crossings(RecoveryMesh& m, const Target& g, Crossings& out);

}  // namespace tubemesh::tets
