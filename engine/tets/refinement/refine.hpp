#pragma once
// Interior points of the tet step (paper §5, third paragraph): advancing-front ideal points
// inserted in parallel batches by the Delaunay kernel in constrained mode, whose cavities never
// cross a front face. Round after round the active front (faces between the resolved region,
// or the front, and tets still too big for h) proposes points (interior_points.hpp), the ones
// far enough from existing points and from each other are inserted, until no tet is too big or
// a round adds nothing.
#include <functional>
#include <cstdint>
#include <vector>

#include "engine/core/parallelism.hpp"
#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

class ControlSpace;

struct RefineOptions {
    // A tet is too big when its mean edge exceeds this times the mean h at its points; 1.3.
    double size_tolerance = 1.3;
    // A candidate closer than this times h to a point (or an accepted candidate) is dropped; 0.7.
    double reject_factor = 0.7;
    // Far-field lattice (interior_points.hpp, FarLattice): cube edge over S (0: off) and the
    // least distance of a lattice point from the front's nodes, over S. Defaults 1.12 and 0.85:
    // the far field's mean collapse rises for few more elements (bench/results/tuning-notes.md).
    double lattice_spacing = 1.12;
    double lattice_clearance = 0.85;
    // Insert the far-field lattice's nodes (FarLattice) all at once, in BRIO rounds, before the
    // first round: the advancing front then fills only the graded layers between the front and
    // the far field, in few rounds, and its cavities no longer reach across the unrefined core.
    // The same nodes the faces would snap to one layer at a time; no effect without the
    // lattice, or when the region fills less than an eighth of its bounding box (the nodes
    // outside it would each cost a walk). Default on.
    bool far_field_first = true;
    // Kernel passes with fewer points per part run serially; 256.
    index_t min_points_per_part = 256;
    // Upper bound on rounds (each adds a layer of points); 200.
    unsigned max_rounds = 200;
    // Called after each round with the tets in the mesh, which only grow from round to round; it
    // may throw to stop the refinement (the pipeline's element cap). May be empty.
    std::function<void(index_t tets)> round_done;
};

struct RefineStats {
    unsigned rounds = 0;
    std::uint64_t candidates = 0;         // proposed inside the region
    std::uint64_t rejected_close = 0;     // too close to a point or an accepted candidate
    std::uint64_t inserted = 0;           // new points in the mesh
    std::uint64_t far_field_first = 0;    // of which inserted before the first round (far_field_first)
    std::uint64_t blocked = 0;            // skipped by the kernel (cavity would lose the point's tet,
                                          // or a far-field node outside the region)
    std::uint64_t duplicates = 0;
    std::uint64_t shrunk_cavities = 0;    // cavities made star-shaped by shrinking
    std::uint64_t kernel_conflicts = 0;   // kernel insertions postponed between parts
    std::uint64_t exact_insphere = 0;     // kernel conflict tests the filter left to exact arithmetic
    std::uint64_t exact_insphere_reused = 0;  // of which answered again within one cavity
    std::uint64_t size_tests = 0;         // tets tested against the size field (each slot once per change)
    std::uint64_t proposals_reused = 0;   // active faces whose ideal point came from an earlier round
    index_t too_big_left = 0;             // active faces when refinement stopped
    index_t tets = 0;
    double seconds = 0;
};

// Keeps TetDomain's invariants: existing points and front unchanged, new points appended,
// all tets positive, no free slots. Throws tubemesh::Error on an empty domain.
// With `sizes`, also the target size h at every point of the result by id (the control space's
// at the points there before, each inserted point's from its candidate), for the relaxation.
// The kernel inserts with par.parts parts, in the caller's oneTBB arena: the same input and part
// count give the same mesh whatever the thread count.
// With `relax_base` (the recovered tets, for the relaxation): when the far field went in first,
// its points (right after the points there before refinement) are marked to stay in place
// (RecoveredTets::in_place).
RefineStats refine_interior(TetDomain& domain, const ControlSpace& space, const Parallelism& par,
                            const RefineOptions& options = {}, std::vector<double>* sizes = nullptr,
                            const Pulse& pulse = {}, RecoveredTets* relax_base = nullptr);

}  // namespace tubemesh::tets
