#pragma once
// Connectivity of one ring: its hexes and its wall, outer and end quads, from the node
// numbering of TubeRing (node (i, j, k) = first + (i·(L+1) + j)·n + k).
//
// For rings that turn right-handed about the tangent (turn = +1) the hex between stations i
// and i+1, layers j and j+1, nodes k and k+1 is (a b c d a' b' c' d') with a = (i, j, k),
// b = (i, j+1, k), c = (i, j+1, k+1), d = (i, j, k+1) and primes at station i+1: a -> b -> c
// runs outwards then round, counter-clockwise seen from station i+1, as VTK wants the bottom
// seen from the top. Its faces (topology.hpp, outward): wall (3 0 4 7), outer (1 2 6 5),
// first end (0 3 2 1), last end (4 5 6 7). A left-handed ring mirrors everything: the hex
// becomes (a d c b a' d' c' b') and every quad is reversed.
#include <array>

#include "engine/core/types.hpp"

namespace tubemesh::sweep {

struct RingCells {
    index_t first = 0;  // node (0, 0, 0)
    index_t n = 0, layers = 0;
    int turn = 1;

    index_t node(index_t i, index_t j, index_t k) const { return first + (i * (layers + 1) + j) * n + k % n; }

    std::array<index_t, 8> hex(index_t i, index_t j, index_t k) const {
        const index_t a = node(i, j, k), b = node(i, j + 1, k), c = node(i, j + 1, k + 1), d = node(i, j, k + 1);
        const index_t a2 = node(i + 1, j, k), b2 = node(i + 1, j + 1, k), c2 = node(i + 1, j + 1, k + 1),
                      d2 = node(i + 1, j, k + 1);
        if (turn > 0) return {a, b, c, d, a2, b2, c2, d2};
        return {a, d, c, b, a2, d2, c2, b2};
    }
    // Wall quad of sector k between stations i and i+1: normal into the hole.
    std::array<index_t, 4> wall_quad(index_t i, index_t k) const {
        return oriented({node(i, 0, k + 1), node(i, 0, k), node(i + 1, 0, k), node(i + 1, 0, k + 1)});
    }
    // Outer quad: normal away from the pipe.
    std::array<index_t, 4> outer_quad(index_t i, index_t k) const {
        return oriented({node(i, layers, k), node(i, layers, k + 1), node(i + 1, layers, k + 1), node(i + 1, layers, k)});
    }
    // End quad of layer j, sector k at `station` (0 or the last): normal out of the ring.
    std::array<index_t, 4> end_quad(index_t station, bool last, index_t j, index_t k) const {
        const index_t a = node(station, j, k), b = node(station, j + 1, k), c = node(station, j + 1, k + 1),
                      d = node(station, j, k + 1);
        return last ? oriented({a, b, c, d}) : oriented({a, d, c, b});
    }

private:
    std::array<index_t, 4> oriented(std::array<index_t, 4> q) const {
        if (turn < 0) return {q[3], q[2], q[1], q[0]};
        return q;
    }
};

}  // namespace tubemesh::sweep
