#include "engine/tets/optimise/point_insertion.hpp"

#include <algorithm>
#include <limits>

#include "engine/predicates/predicates_inline.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {

using delaunay::kNoAdjacent;

namespace {

bool in_cavity(const FlipPlan& plan, index_t t) {
    return std::find(plan.old_tets.begin(), plan.old_tets.begin() + plan.old_count, t) !=
           plan.old_tets.begin() + plan.old_count;
}

// What build_cone found: the cone is complete, or x does not see a boundary face (orient3d
// <= 0) and the cavity must grow into the tet behind it, or it cannot (a front face: x is
// outside the region there; or more faces than a plan holds).
enum class Cone { Complete, Grow, Refused };

// Fills plan.new_tets with x joined to every boundary face of the cavity plan.old_tets, until
// the first face x does not see; `grow_into` is then the tet behind it.
Cone build_cone(const TetDomain& dom, const double* x, FlipPlan& plan, index_t& grow_into) {
    const index_t apex = dom.point_count();
    plan.new_count = 0;
    for (int i = 0; i < plan.old_count; ++i) {
        const index_t t = plan.old_tets[i];
        const index_t* v = dom.tets.vertex(t);
        for (index_t f = 0; f < 4; ++f) {
            const index_t n = dom.tets.neighbour(4 * t + f);
            if (n != kNoAdjacent && in_cavity(plan, n >> 2)) continue;
            const auto& l = kTetFaceToward[f];
            const index_t a = v[l[0]], b = v[l[1]], c = v[l[2]];
            if (predicates::orient3d_inline(dom.point(a), dom.point(b), dom.point(c), x) <= 0) {
                if (n == kNoAdjacent) return Cone::Refused;
                grow_into = n >> 2;
                return Cone::Grow;
            }
            if (plan.new_count == FlipPlan::kMaxNew) return Cone::Refused;
            plan.new_tets[plan.new_count++] = {a, b, c, apex};
        }
    }
    return Cone::Complete;
}

}  // namespace

bool plan_point_insertion(const TetDomain& dom, index_t t, const Vec3& x, FlipPlan& plan,
                          const double* slot_collapse) {
    const double xp[3] = {x.x, x.y, x.z};
    plan.kind = FlipKind::PointInsertion;
    plan.old_count = 1;
    plan.old_tets[0] = t;
    index_t grow_into = kNoIndex;
    for (Cone c; (c = build_cone(dom, xp, plan, grow_into)) != Cone::Complete;) {
        if (c == Cone::Refused || plan.old_count == FlipPlan::kMaxOld) return false;
        plan.old_tets[plan.old_count++] = grow_into;
    }
    plan.old_min = min_collapse_of_tets(dom, plan.old_tets.data(), plan.old_count, &plan.old_sum, slot_collapse);
    plan.new_min = std::numeric_limits<double>::infinity();
    plan.new_sum = 0;
    for (int j = 0; j < plan.new_count; ++j) {
        const auto& n = plan.new_tets[j];
        const double q = tet_collapse({point_vec(dom, n[0]), point_vec(dom, n[1]), point_vec(dom, n[2]), x});
        plan.new_min = std::min(plan.new_min, q);
        plan.new_sum += q;
    }
    return true;
}

}  // namespace tubemesh::tets
