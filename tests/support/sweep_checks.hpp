#pragma once
// What the sweep's acceptance asks of every ring, measured independently of the sweep's own
// statistics: hex quality from the mesh, wall nodes on the analytic wall, end nodes on the
// analytic host, and `tubemesh check` on the ring mesh alone.
#include "engine/check/mesh_check.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace tubemesh::sweep_testing {

struct RingFigures {
    index_t hexes = 0;
    double min_jacobian = 0, mean_jacobian = 0, max_condition = 0;
    double wall_error = 0;  // largest distance of a wall node from its tube's wall, over r
    double host_error = 0;  // largest distance of an end node from its host, over r
    CheckReport check;      // the ring mesh with its outer quads added as boundary faces
};

RingFigures measure_rings(const Scene& scene, const HybridMesh& mesh, const SweepResult& result);

// The outer quads appended to the mesh's boundary quads (group "ring_outer"), so the ring
// mesh's free surface is fully covered for check_mesh.
HybridMesh with_outer_quads(HybridMesh mesh, const SweepResult& result);

// Sweeps the scene into a fresh mesh (with scene.options() unless given) and checks the acceptance bar: J_m >= 0.5, Cond <= 4,
// mean J_m >= 0.70, nodes on wall and hosts within 1e-7 r, check_mesh clean. Returns the
// figures for reporting.
RingFigures expect_acceptance(const Scene& scene);
RingFigures expect_acceptance(const Scene& scene, const SweepOptions& options);

}  // namespace tubemesh::sweep_testing
