#pragma once
// Where a front quad has an edge on a boundary face (the last station's outer quads of a ring,
// whose end edge lies on the host face), the tet region between the pyramid's lateral face over
// that edge and the boundary triangle under it is a wedge with both faces fixed before the tets
// are made: one tet fills it, and its dihedral at the edge is the wedge's angle. Over a host met
// at a right angle an apex at height H over the centroid leaves atan(a/2 / H) for an end quad
// of axial length a. The paper's apex (H = 0.98 h, 31.5 degrees on the default rings) is too
// close to the host for its distance rule there, so the first try node served (0.88 h, 34
// degrees), which caps that tet's collapse near 0.29, the worst of a whole dam lift. Such
// fronts get an ideal apex lowered and shifted along the quad away from the edge until the
// wedge reaches a target angle.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/pyramids/build_pyramids.hpp"

namespace tubemesh::pyramids {

// The boundary triangles' edges, each with the third node of the triangle that holds it,
// sorted by edge for lookup.
class BoundaryEdges {
public:
    explicit BoundaryEdges(std::span<const index_t> triangles);
    // The third node of the only boundary triangle on edge (a, b); kNoIndex when no boundary
    // triangle or more than one holds the edge.
    index_t opposite(index_t a, index_t b) const;

private:
    std::vector<std::pair<std::uint64_t, index_t>> edges_;
    // Per node id up to the largest in a triangle: it is a triangle's node. Most front quads have
    // no such node, and their edges are not searched for.
    std::vector<bool> on_boundary_;
};

// The ideal apex of one front as an offset from its centroid M: N = M + shift + height·n.
struct ApexPlacement {
    Vec3 shift{0, 0, 0};  // in the quad's plane
    double height = 0;
    bool wedge = false;  // placed to open a wedge, not the paper's
};

// The paper's apex (no shift, height_factor·h) unless an edge of the quad lies on a boundary
// triangle and leaves a wedge narrower than opt.wedge_degrees under the paper's lateral face;
// then the apex at opt.wedge_height_factor·h, shifted away from that edge just enough to open
// the wedge to opt.wedge_degrees, at most max_shift of the quad's length (the options'
// wedge_max_shift, or their wedge_wide_shift for a front's second apex). Each such edge adds
// its shift: a quad with boundary triangles on two opposite edges (a tube one station long)
// gets shifts that cancel, and its wedges stay as the lowered apex leaves them.
// The caller judges the placed pyramid's quality (fronts.cpp).
ApexPlacement place_apex(const HybridMesh& mesh, const index_t* quad, const Vec3& centroid, const Vec3& normal,
                         double h, const BoundaryEdges& boundary, const PyramidOptions& opt, double max_shift);

}  // namespace tubemesh::pyramids
