#pragma once
// Tubes that continue through a face, as a pipe crossing from one solid of an assembly into
// the next: the two rings' cross-sections on that face become one, node for node, so the hexes
// on both sides share their quads there.
#include <vector>

#include "engine/sweep/sweep.hpp"

namespace tubemesh {

struct RingJoin {
    index_t tube_a = 0, tube_b = 0;  // indices into the swept tubes, tube_a < tube_b
    int end_a = 0, end_b = 0;        // 0: the ring1 end, 1: the ring2 end
};

// The pipe of every one of `tubes` tubes, numbered from 0: a chain of joined tubes is one pipe,
// and the pipes are numbered in the order of their first tubes, without gaps.
std::vector<index_t> pipe_of_tubes(std::size_t tubes, const std::vector<RingJoin>& joins);

// For every join, tube_b's nodes on its end station are replaced by tube_a's at the same place
// wherever tube_b's hexes, quads and RingEnds use them; those nodes stay in the mesh unused
// (the caller drops them). tube_b's end quads there leave the boundary quads (tube_a's stay,
// in the face's group: interior faces now), its RingEnd there gets host 0 (the face keeps one
// hole, tube_a's), and every tube of a chain takes the wall group of the chain's first tube:
// one pipe, one group, named "pipe_<k>" with k = pipe_of_tubes + 1 (the groups left empty take
// the numbers after the last pipe's). Returns the largest distance between two nodes made one.
// Throws tubemesh::Error when the cross-sections differ in size or a node of one has no node
// of the other within `tolerance`.
double join_ring_ends(HybridMesh& mesh, SweepResult& sweep, const std::vector<RingJoin>& joins, double tolerance);

}  // namespace tubemesh
