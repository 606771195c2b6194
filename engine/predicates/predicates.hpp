#pragma once
// The one geometric predicates module of tubemesh: exact signs of orient3d and insphere
// (floating-point filter, then exact integer or expansion arithmetic), symbolic perturbation
// for ties, and segment/triangle and triangle/triangle intersection built on them.
// Compiled in its own target with -ffp-contract=off: a contracted multiply-add would break the
// error-free transformations of the expansion arithmetic (expansion.hpp). The filters' error
// bounds survive contraction (filters.hpp), which is why predicates_inline.hpp may inline them.
//
// Points are `const double*` to 3 coordinates, so callers can pass SoA-gathered or AoS data.
// Every result is exact for any finite coordinates (tiny, huge and subnormal included); for NaN
// or infinite coordinates the result is unspecified.
//
// orient3d and insphere cost a few ns when the filter decides, as it does for points in general
// position; exact ties and near-ties cost tens to a few hundred ns (exact.hpp).
// predicates_inline.hpp has the same two with the filter inlined, for inner loops.
#include <cstdint>

#include "engine/core/vec3.hpp"

namespace tubemesh::predicates {

// Sign of det[b-a, c-a, d-a]: +1 when (a,b,c,d) is a positively oriented tet (a,b,c
// counter-clockwise seen from d, the mesh store's convention), -1 when negative, 0 coplanar.
int orient3d(const double* a, const double* b, const double* c, const double* d);

// +1 when e lies strictly inside the circumsphere of the positively oriented tet (a,b,c,d),
// -1 outside, 0 on it. For a negatively oriented tet the sign flips.
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

// Symbolically perturbed versions (Simulation of Simplicity, sos.cpp): the exact sign when it
// is not 0, else the sign after perturbing the points infinitesimally, by amounts ordered by the
// caller's global point indices (the largest index moves most). Both use one perturbation of
// one point set, so co-planar and co-spherical ties are decided the same way everywhere and a
// Delaunay triangulation built from them is consistent. For insphere, lifting is perturbed
// before position: a tie with a tet that is not flat is decided by the orient3d of the four
// points other than the one with the largest index (then the next largest, ...), as in Geogram
// and CGAL. Never 0 for pairwise distinct indices, even for coincident points. With a repeated
// index the result is the unperturbed sign, which may be 0.
int orient3d_sos(const double* a, const double* b, const double* c, const double* d, std::uint32_t ia,
                 std::uint32_t ib, std::uint32_t ic, std::uint32_t id);
int insphere_sos(const double* a, const double* b, const double* c, const double* d, const double* e,
                 std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id, std::uint32_t ie);
// insphere_sos for a caller whose own insphere filter (filters.hpp) has abstained: the same
// result without evaluating the filter a second time.
int insphere_sos_unfiltered(const double* a, const double* b, const double* c, const double* d, const double* e,
                            std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id,
                            std::uint32_t ie);

// Intersection of closed simplices, decided exactly.
enum class Contact : std::uint8_t {
    None,      // disjoint
    Touching,  // they meet only on the boundary of one of them (a shared vertex, an endpoint
               // on the triangle, collinear/coplanar overlap)
    Crossing,  // the relative interiors cross
};
// Coplanar configurations are at most Touching, even when the relative interiors overlap, and
// so is any contact with a degenerate (collinear) triangle or segment, which has no interior.
// Crossing therefore means a transversal crossing: the segment's interior passes through the
// triangle's interior, or the two triangles' interiors cut each other along a segment.

// Segment pq against triangle abc.
Contact segment_triangle(const double* p, const double* q, const double* a, const double* b, const double* c);

// Triangle abc against triangle def.
Contact triangle_triangle(const double* a, const double* b, const double* c, const double* d, const double* e,
                          const double* f);

// orient3d and segment_triangle on Vec3 points.
inline int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z}, pc[3] = {c.x, c.y, c.z}, pd[3] = {d.x, d.y, d.z};
    return orient3d(pa, pb, pc, pd);
}
inline Contact segment_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    const double pp[3] = {p.x, p.y, p.z}, pq[3] = {q.x, q.y, q.z};
    const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z}, pc[3] = {c.x, c.y, c.z};
    return segment_triangle(pp, pq, pa, pb, pc);
}

}  // namespace tubemesh::predicates
