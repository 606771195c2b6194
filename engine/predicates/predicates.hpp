#pragma once
// The one geometric predicates module of tubemesh: exact signs of orient3d and insphere
// (floating-point filter, exact expansion arithmetic as fallback), symbolic perturbation for
// ties, and segment/triangle and triangle/triangle intersection built on them.
// Compiled in its own target with -ffp-contract=off: a fused multiply-add would change the
// rounding the filters' error bounds are derived for.
//
// Points are `const double*` to 3 coordinates, so callers can pass SoA-gathered or AoS data.
#include <cstdint>

namespace tubemesh::predicates {

// Sign of det[b-a, c-a, d-a]: +1 when (a,b,c,d) is a positively oriented tet (a,b,c
// counter-clockwise seen from d, the mesh store's convention), -1 when negative, 0 coplanar.
int orient3d(const double* a, const double* b, const double* c, const double* d);

// +1 when e lies strictly inside the circumsphere of the positively oriented tet (a,b,c,d),
// -1 outside, 0 on it. For a negatively oriented tet the sign flips.
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

// Symbolically perturbed versions (Simulation of Simplicity, perturbation ordered by the
// caller's global point indices): never 0 for distinct indices and distinct points, and
// consistent across calls, so co-planar and co-spherical ties are decided the same way
// everywhere. Only orient3d of four identical-position points can still return 0.
int orient3d_sos(const double* a, const double* b, const double* c, const double* d, std::uint32_t ia,
                 std::uint32_t ib, std::uint32_t ic, std::uint32_t id);
int insphere_sos(const double* a, const double* b, const double* c, const double* d, const double* e,
                 std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id, std::uint32_t ie);

// Intersection of closed simplices, decided exactly.
enum class Contact : std::uint8_t {
    None,      // disjoint
    Touching,  // they meet only on the boundary of one of them (a shared vertex, an endpoint
               // on the triangle, collinear/coplanar overlap)
    Crossing,  // the relative interiors cross
};

// Segment pq against triangle abc.
Contact segment_triangle(const double* p, const double* q, const double* a, const double* b, const double* c);

// Triangle abc against triangle def.
Contact triangle_triangle(const double* a, const double* b, const double* c, const double* d, const double* e,
                          const double* f);

}  // namespace tubemesh::predicates
