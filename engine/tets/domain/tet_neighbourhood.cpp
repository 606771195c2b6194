#include "engine/tets/domain/tet_neighbourhood.hpp"

#include <algorithm>

#include "engine/predicates/predicates_inline.hpp"

namespace tubemesh::tets {

using delaunay::kNoAdjacent;

bool positively_oriented(const TetDomain& dom, const std::array<index_t, 4>& v) {
    return predicates::orient3d_inline(dom.point(v[0]), dom.point(v[1]), dom.point(v[2]), dom.point(v[3])) > 0;
}

void vertex_star(const TetDomain& dom, index_t seed, index_t p, std::vector<index_t>& star) {
    star.clear();
    star.push_back(seed);
    for (std::size_t k = 0; k < star.size(); ++k) {
        const index_t t = star[k];
        const index_t* v = dom.tets.vertex(t);
        for (index_t f = 0; f < 4; ++f) {
            if (v[f] == p) continue;  // the one face of t that does not hold p
            const index_t n = dom.tets.neighbour(4 * t + f);
            if (n == kNoAdjacent) continue;
            const index_t u = n >> 2;
            // Stars hold a few tens of tets: a linear scan beats any set.
            if (std::find(star.begin(), star.end(), u) == star.end()) star.push_back(u);
        }
    }
}

namespace {

// Parity of the permutation (i0, i1, i2, i3) of (0, 1, 2, 3): true when odd.
bool odd_permutation(const std::array<int, 4>& p) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
    return inversions % 2 == 1;
}

}  // namespace

bool edge_shell(const TetDomain& dom, index_t seed, int local_a, int local_b, int max_size, EdgeShell& shell) {
    const index_t* v = dom.tets.vertex(seed);
    std::array<int, 4> order{local_a, local_b, 0, 0};
    int k = 2;
    for (int i = 0; i < 4; ++i)
        if (i != local_a && i != local_b) order[k++] = i;
    // (a, b, c, d) inherits the seed's positive orientation through an even permutation.
    if (odd_permutation(order)) std::swap(order[2], order[3]);
    shell.a = v[order[0]];
    shell.b = v[order[1]];
    shell.tets[0] = seed;
    shell.ring[0] = v[order[2]];
    shell.ring[1] = v[order[3]];
    shell.size = 1;
    index_t current = seed, back = shell.ring[0];
    for (;;) {
        const index_t n = dom.tets.neighbour(4 * current + static_cast<index_t>(local_index(dom, current, back)));
        if (n == kNoAdjacent) return false;
        const index_t next = n >> 2;
        if (next == seed) return true;
        if (shell.size == max_size || shell.size == EdgeShell::kMaxSize) return false;
        const index_t apex = dom.tets.vertex(next)[n & 3];
        back = shell.ring[shell.size];
        shell.tets[shell.size] = next;
        ++shell.size;
        // The ring closes onto ring[0] when the walk returns to the seed; only store new apices.
        if (shell.size < EdgeShell::kMaxSize) shell.ring[shell.size] = apex;
        current = next;
    }
}

}  // namespace tubemesh::tets
