#pragma once
// Insertion order for incremental Delaunay: BRIO (biased randomized insertion order, Amenta,
// Choi & Rote 2003) with every round sorted along a 3-D Hilbert curve. Rounds keep the
// triangulation well shaped as it grows; the curve keeps consecutive points close, so the
// point-location walk from the previous insertion is a few steps long.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.hpp"

namespace tubemesh::delaunay {

// Hilbert index of a point on a 2^bits grid per axis (bits <= 21), 3*bits significant bits.
std::uint64_t hilbert_key(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz, int bits);

// The order of the points (3 coordinates each) along the Hilbert curve on a 2^16 grid over
// their bounding cube, equal keys in input order: indices into the points. For a batch of
// points inserted into an existing mesh: consecutive points are close, so each walk from the
// previous insertion is short.
std::vector<index_t> curve_order(std::span<const double> xyz);

struct InsertionOrder {
    std::vector<index_t> order;        // point ids in insertion order
    std::vector<index_t> round_begin;  // round r is order[round_begin[r], round_begin[r+1])
    std::vector<std::uint64_t> key;    // Hilbert key of order[k]
    // The curve's grid: a cube over the points' bounding box.
    double grid_lo[3] = {0, 0, 0};
    double grid_scale = 0;  // cells per unit length

    // Key of any point on the same curve (points outside the grid go to its border cells).
    std::uint64_t key_of(double x, double y, double z) const;
};

// Rounds are drawn with a hash of the point id and a fixed seed, so the order is a pure
// function of the input: round sizes grow by about 8x, the last holds about 7/8 of the
// points. Odd rounds run the curve backwards, so a round starts where the previous ended.
InsertionOrder brio_hilbert_order(std::span<const double> x, std::span<const double> y,
                                  std::span<const double> z);

}  // namespace tubemesh::delaunay
