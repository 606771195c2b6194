#pragma once
// Local neighbourhoods in a TetDomain that the optimisation reads: the tets around a point
// (its star), the ring of tets around an edge (its shell), the collapse of four point ids.
// Every walk follows the neighbour codes only, so it works while free slots exist.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/quality/quality.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

// Face f of a positively oriented tet (v0, v1, v2, v3), ordered counter-clockwise seen from
// vertex f: (face[0], face[1], face[2], v_f) is again positively oriented.
inline constexpr std::array<std::array<std::uint8_t, 3>, 4> kTetFaceToward{{{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

inline Vec3 point_vec(const TetDomain& d, index_t p) {
    const double* c = d.point(p);
    return {c[0], c[1], c[2]};
}

// tet_collapse of the tet (a, b, c, d) in that order: negative when it is inverted.
inline double collapse_of(const TetDomain& dom, index_t a, index_t b, index_t c, index_t d) {
    return tet_collapse({point_vec(dom, a), point_vec(dom, b), point_vec(dom, c), point_vec(dom, d)});
}
inline double collapse_of(const TetDomain& dom, const std::array<index_t, 4>& v) {
    return collapse_of(dom, v[0], v[1], v[2], v[3]);
}

// collapse_of for two tets (rows a and b of four point ids), written to q[0] and q[1]: the same
// bits as two collapse_of calls, in about the time of one.
inline void collapse_of_pair(const TetDomain& dom, const index_t* a, const index_t* b, double q[2]) {
#if TUBEMESH_VEC3_PAIR
    std::array<Vec3Pair, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = pair_of(point_vec(dom, a[i]), point_vec(dom, b[i]));
    _mm_storeu_pd(q, tet_collapse_pair(p));
#else
    q[0] = collapse_of(dom, a[0], a[1], a[2], a[3]);
    q[1] = collapse_of(dom, b[0], b[1], b[2], b[3]);
#endif
}

// Exact sign test: orient3d(a, b, c, d) > 0.
bool positively_oriented(const TetDomain& dom, const std::array<index_t, 4>& v);

// Local index of point p in tet t, or 4 when p is not a vertex of t.
inline int local_index(const TetDomain& dom, index_t t, index_t p) {
    const index_t* v = dom.tets.vertex(t);
    for (int i = 0; i < 4; ++i)
        if (v[i] == p) return i;
    return 4;
}

// Appends to `star` (cleared first) every tet that has point p as a vertex, starting from the
// tet `seed`, which must have p as a vertex. Order: breadth first from the seed, neighbours in
// face order, so the result is a function of the mesh only.
void vertex_star(const TetDomain& dom, index_t seed, index_t p, std::vector<index_t>& star);

// The tets around the edge (a, b), a and b vertices of tet `seed`: tets[i] = (a, b, ring[i],
// ring[i+1 mod n]) positively oriented in that vertex order, tets[0] = seed.
struct EdgeShell {
    static constexpr int kMaxSize = 10;
    index_t a = kNoIndex, b = kNoIndex;
    int size = 0;
    std::array<index_t, kMaxSize> tets{};
    std::array<index_t, kMaxSize> ring{};
};

// False when the shell is open (the edge lies on the front: a face around it has no tet
// behind it) or has more than max_size tets (max_size <= EdgeShell::kMaxSize).
bool edge_shell(const TetDomain& dom, index_t seed, int local_a, int local_b, int max_size, EdgeShell& shell);

}  // namespace tubemesh::tets
