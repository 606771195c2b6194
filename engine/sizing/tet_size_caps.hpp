#pragma once
// Surface triangles the tets beside them could not match, and the local sizes that fix them.
//
// The surface size field (surface_sizing.hpp) grades only from the rings' end polygons, on the
// faces the tubes pass through. A face a tube runs beside — the side wall of a lift 0.5-0.75 m
// from its outer pipe, the top and bottom 1.5 m above the pipes — gets S there. The tet step
// grades its interior points from the whole front (engine/sizing/control_space.hpp: the nearest
// front nodes' sizes, growing by G - 1 per unit distance), so between such a face and the
// pipe it asks for sizes near the pipe's, h_q + (G - 1)·d, well under S: each of the face's
// large triangles is then the base of caps. A 40-pipe lift at S 2.53 had wall triangles of
// 2.5 m against tets of 0.5 m, and its worst tet (collapse 0.226) was such a cap that no flip,
// move or new point could lift.
//
// TetSizeCaps models the size the pipes alone ask for: a SizeField with one source per ring
// outer quad (its centroid, its mean edge), growth max(G - 1, g) with g the surface field's
// own growth. (Not the control space itself: that also takes the surface's nodes, which is
// what hides the pipe from a large triangle. The floor g keeps a small G from capping every
// triangle of a block: the surface cannot grade slower than g anyway.) A triangle whose mean
// edge exceeds kTooLarge times that size at its centroid yields a source asking for kCapped
// times it there. Those sources go into the surface field with its own growth g, so the
// surface's neighbour ratio bound of 1.5 is unchanged, and the faces are meshed again
// (pipeline.cpp).
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/sizing/field/size_field.hpp"

namespace tubemesh {

// A surface triangle may be this many times the volume size at its centroid. A tet on a
// triangle of mean edge a, with its apex at the height the control space asks for (about
// 0.8 h), has collapse about h / a: 2 leaves the optimiser tets near 0.5 to work from.
inline constexpr double kTooLarge = 2.0;
// What a capped place asks for, in volume sizes. The face mesher accepts triangles up to 1.3
// times its target (FaceMeshOptions' accept ratio), so 1.25 keeps the new triangles under
// 1.25 · 1.3 = 1.63 h, clear of kTooLarge; 1.5 left triangles over it (bench/results/tuning-notes.md).
inline constexpr double kCapped = 1.25;

// A worst tet below this collapse is one a too-large triangle may have made: below the reference
// cases' worst tets, above the ones the caps were needed for (bench/results/tuning-notes.md).
inline constexpr double kPoorTet = 0.25;

// The warning for `left` triangles still too large after `passes` surface passes, "" for none.
// With `worst_tet`, the tets' smallest collapse once they are made: only when it is below kPoorTet;
// without (the run stopped before the tets): that they may be flat.
std::string too_large_warning(std::size_t left, int passes, std::optional<double> worst_tet);

class TetSizeCaps {
public:
    // `outer_quads`: 4 node ids per ring outer quad (SweepResult::outer_quads); `far_size` S;
    // `gradation` the tet step's G (>= 1); `surface_growth` g (> 0). Throws tubemesh::Error
    // for a G below 1 or a g not positive. `quad_scale` (SweepResult::outer_quad_scale, may be
    // empty): a quad over a ring thinned to that share of St asks for that share of its mean
    // edge, the size of the thin gap in front of it.
    TetSizeCaps(const HybridMesh& mesh, std::span<const index_t> outer_quads, double far_size, double gradation,
                double surface_growth, std::span<const double> quad_scale = {});
    ~TetSizeCaps();
    TetSizeCaps(const TetSizeCaps&) = delete;
    TetSizeCaps& operator=(const TetSizeCaps&) = delete;

    // Sources for the triangles [first_triangle, end) of mesh's triangle block that are too
    // large for the tets beside them; empty when none is or there are no quads. Deterministic
    // (triangle order), parallel.
    std::vector<SizeSource> caps(const HybridMesh& mesh, index_t first_triangle) const;

private:
    std::unique_ptr<SizeField> volume_;  // null without quads
};

}  // namespace tubemesh
