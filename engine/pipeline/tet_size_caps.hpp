#pragma once
// Surface triangles the tets beside them could not match, and the local sizes that fix them.
//
// The surface size field (surface_sizing.hpp) grades only from the rings' end polygons, on the
// faces the tubes pass through. A face a tube runs beside — the side wall of a lift 0.75 m
// from its outer pipe, the top and bottom 1.5 m above the pipes — gets S there. The tet
// step's control space (engine/tets/control_space.hpp) grades from the rings' outer quads
// instead: near a pipe it asks for h_q + (G - 1)·d. Where a face sits at a distance d with
// h_q + (G - 1)·d well under S, each of its triangles is the base of caps: a 40-pipe lift at
// S 2.53 had wall triangles of 2.5 m against tets of 0.5 m, and its worst tet (collapse 0.226)
// was such a cap that no flip, move or new point could lift.
//
// tet_size_caps measures every surface triangle against that volume size, computed the same
// way (a SizeField with growth G - 1 and one source per outer quad: its centroid, its mean
// edge). A triangle whose mean edge exceeds kTooLarge times it yields a source asking for
// kCapped times it at the triangle's centroid. Those sources go into the surface field with
// its own growth (0.25), so the surface's neighbour ratio bound of 1.5 is unchanged, and the
// faces are meshed again (pipeline.cpp).
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/surface/size_field.hpp"

namespace tubemesh {

// A surface triangle may be this many times the volume size at its centroid. A tet on a
// triangle of mean edge a, with its apex at the height the control space asks for (about
// 0.8 h), has collapse about h / a: 2 leaves the optimiser tets near 0.5 to work from.
inline constexpr double kTooLarge = 2.0;
// What a capped place asks for, in volume sizes. The face mesher accepts triangles up to 1.3
// times its target (FaceMeshOptions' accept ratio), so 1.25 keeps the new triangles under
// 1.25 · 1.3 = 1.63 h, clear of kTooLarge: with 1.5 (up to 1.95 h) the serpentine lift's side
// walls kept 4 triangles at 2.07 h through six passes.
inline constexpr double kCapped = 1.25;

// Sources for the surface triangles [first_triangle, end) of mesh's triangle block that are
// too large for the tets the control space would put beside them. `outer_quads`: 4 node ids per
// ring outer quad (SweepResult::outer_quads); `far_size` S; `gradation` the tet step's G (>= 1).
// Empty when nothing is too large or there are no quads. Deterministic (triangle order).
std::vector<SizeSource> tet_size_caps(const HybridMesh& mesh, std::span<const index_t> outer_quads,
                                      index_t first_triangle, double far_size, double gradation);

}  // namespace tubemesh
