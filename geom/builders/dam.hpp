#pragma once
// A parametric concrete dam for batch meshing: C columns side by side along the dam's axis,
// each cast in L lifts, every lift block cooled by its own serpentine pipe. Sizes, pipe
// diameter, run spacing, bend radius and the inlet's end of the downstream face vary per block
// within the ranges below, drawn from a seed: the same seed gives the same dam.
//
// Axes: x along the dam's axis (a column's width), y from the upstream face (y = 0) to the
// downstream face (y = depth), z up. The pipe's runs go upstream and back, its inlet and
// outlet on the downstream face. Each block is built in its own frame (corner at the origin);
// `origin` places it in the dam.
#include <cstdint>
#include <string>
#include <vector>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

struct Range {
    double lo = 0, hi = 0;  // a value is drawn uniformly in [lo, hi]
};

struct DamParams {
    int columns = 3;
    int lifts = 4;
    std::uint64_t seed = 1;
    Range width{15, 20};         // per column, along the dam's axis
    Range depth{12, 18};         // per column, upstream to downstream
    Range lift_height{1.5, 3};   // per block
    Range diameter{0.025, 0.040};  // of the pipe, per block
    Range spacing{1.0, 2.0};     // between neighbouring runs, per block
    // Bend radius per block as a share of its spacing: at most 1/2 (serpentine_spec's limit).
    Range bend_share{0.4, 0.5};
    // The foundation and crest blocks go without a pipe (below); false gives every block one.
    bool pipeless_ends = true;
    // The serpentines' centre above each lift's bottom, in pipe radii (a cooling pipe laid on the
    // lift joint: about 1.5); 0: at mid-height.
    double pipe_height_radii = 0;
    // Straight pipes along the dam's axis (x), each through every column of one lift at a
    // quarter of the lift's common height, below the serpentines: coils laid over a whole lift,
    // crossing the column joints. Each block a pipe passes holds its piece, from face x- to x+.
    // At most one per lift; the lifts taken are spread from the lowest up.
    int crossing_pipes = 0;
};

struct DamBlock {
    std::string id;  // "c2-l03": column and lift, 1-based, zero-padded to the largest
    int column = 0, lift = 0;
    Vec3 origin;     // the block's corner in the dam
    BlockSpec spec;  // a box with one serpentine pipe, or none
    std::string role;  // "lift", or "foundation" / "crest" for the blocks without a pipe
};

// Column by column, lift by lift upwards. The foundation block (first column, first lift) and
// the crest block (last column, top lift) have no pipe when the dam has three blocks or more.
// Throws tubemesh::Error on counts below 1, empty or inverted ranges, or sizes a serpentine
// cannot fit.
std::vector<DamBlock> dam_blocks(const DamParams& params);

}  // namespace tubemesh::geom
