#pragma once
// The whole tet step (paper §5) on the pipeline's mesh: the closed front (PipelineResult::
// tet_front, mesh node ids) -> boundary recovery -> control space -> interior points -> ODT
// relaxation -> optimisation -> new points and tets appended to the HybridMesh.
//
// The front's nodes keep their mesh ids; Steiner points of the recovery, interior points and
// the optimisation's rescue points become new mesh points, appended in the domain's order, so
// the numbering is deterministic.
// The mesh's existing cells and boundary faces are not touched: the front triangles become
// faces shared by a tet and a pyramid / hex-free side (pyramid layer) or boundary faces on
// the solid's surface (their group stays).
#include <cstdint>
#include <functional>
#include <span>

#include "engine/core/parallelism.hpp"
#include "engine/core/pulse.hpp"
#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/tets/recovery/boundary_recovery.hpp"
#include "engine/sizing/control_space.hpp"
#include "engine/tets/refinement/odt_relaxation.hpp"
#include "engine/tets/optimise/optimise.hpp"
#include "engine/tets/refinement/refine.hpp"

namespace tubemesh::tets {

struct TetStepOptions {
    // Far size S of the control space (the pipeline passes DiscreteGeometry::size). 0: the
    // largest local size of the front.
    double far_size = 0;
    // Largest growth of the target size from one tet to the next (ControlSpaceOptions); 1.6:
    // most tets of a hybrid mesh sit in the transition from the rings' small quads to S, so the
    // gradation sets the element count (bench/results/tuning-notes.md has the trade-off).
    double gradation = 1.6;
    RecoveryOptions recovery;
    RefineOptions refine;
    RelaxationOptions relaxation;
    OptimiseOptions optimise;
    // Let the optimisation's smoothing move the pyramid apexes that only pyramids and tets hold,
    // each pyramid kept at a scaled Jacobian of at least apex_floor: the tets between pyramids
    // (three apexes and one free point) are then no longer fixed. Off by default: the tets'
    // minimum and mean rise, the pyramids' fall towards the floor, and the optimisation takes
    // longer (bench/results/tuning-notes.md).
    bool move_apexes = false;
    double apex_floor = 0.5;
    // Let the smoothing slide the surface nodes inside flat faces of the solid in their plane:
    // nodes of the mesh's boundary triangles whose triangles are all front triangles of one
    // surface group and lie in one plane (nodes of CAD edges, curved faces, rings and pyramids
    // stay). The tets on the solid's surface are then no longer fixed; the solid's shape and the
    // surface groups do not change. On the reference cases and seeds 1-50 the tets' minimum never
    // fell and the mean rose (bench/results/tuning-notes.md).
    bool slide_surface = true;
    // Called after each of the three parts (recovery, refinement with the relaxation,
    // optimisation), for progress reports; may be empty. The mesh does not depend on it.
    std::function<void()> part_done;
    // Called between the steps of each part (engine/core/pulse.hpp); may be empty.
    Pulse pulse;
};

struct TetStepStats {
    RecoveryStats recovery;
    RefineStats refine;
    RelaxationStats relaxation;
    OptimiseStats optimise;
    index_t front_triangles = 0;
    index_t new_points = 0;  // Steiner + interior points appended to the mesh
    index_t tets = 0;
    unsigned threads = 0, partitions = 0;
    double seconds = 0;
};

// Appends the tets (region `region`) and their new points to `mesh`. `front`: 3 mesh node ids
// per triangle, normal out of the region. Throws tubemesh::Error (mesh unchanged) when the
// front is not a closed, oriented, non-self-intersecting surface or recovery fails. Every part
// runs in the caller's oneTBB arena, its Delaunay passes with par.parts parts: the mesh depends
// on the input and that count only.
TetStepStats build_tets(HybridMesh& mesh, std::span<const index_t> front, index_t region, const Parallelism& par,
                        const TetStepOptions& options = {});

}  // namespace tubemesh::tets
