#pragma once
// Insertion of one new free point into a TetDomain, for the few tets no flip and no move can
// lift. Example: the serpentine lift at --circ 8 --sweep-size 0.128 --layers 3, where the pipe
// bends, has one pyramid's apex 0.01 degrees off the plane of the next pyramid's side face,
// and the tet on that face has the apex as its fourth point (collapse 9e-5). All four points
// are front points, so nothing moves; its 2-3 flips would make inverted tets; removing one of
// its two inner edges leaves a tet as flat (5e-5), the other's ring of 7 has no valid
// triangulation. A point inside the region over the front face gives it, and the faces around
// it, a new apex, which the rescue's moves then place.
//
// The cavity is the smallest set of tets grown from tet t, across faces only, whose every
// boundary face the point x sees strictly from inside (exact orient3d > 0): then the tets
// joining x to those faces fill the cavity exactly (each is positive and their volumes add up
// to the cavity's), so the mesh stays valid. A front face on the cavity's boundary is kept (it
// gets x as its new apex); a front face x does not see means x is outside the region there,
// and the insertion is refused.
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/tets/domain/tet_domain.hpp"
#include "engine/tets/optimise/tet_flips.hpp"

namespace tubemesh::tets {

// Plans inserting x as point dom.point_count() (not yet in dom.xyz: the caller appends it
// before applying the plan with apply_flip). plan.kind is PointInsertion, old_tets the cavity
// (t first), new_tets the cone from x, old_min/old_sum the cavity's collapses (read from
// slot_collapse when given), new_min/new_sum the cone's. False when x is outside the region
// near t, or the cavity needs more than FlipPlan::kMaxOld tets or its cone more than
// FlipPlan::kMaxNew.
bool plan_point_insertion(const TetDomain& dom, index_t t, const Vec3& x, FlipPlan& plan,
                          const double* slot_collapse = nullptr);

}  // namespace tubemesh::tets
