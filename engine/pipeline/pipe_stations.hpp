#pragma once
// Each pipe's stations from the swept rings (MeshDescription::pipes): the rings of a joined pipe
// chained end to end, oriented from the rim named "<pipe>_inlet" to the one named "_outlet".
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/mesh_description.hpp"
#include "engine/sweep/ring_joins.hpp"
#include "engine/sweep/sweep.hpp"

namespace tubemesh {

// Appends one PipeStations per pipe (wall group) to description.pipes, in the order of the
// pipes' first tubes. Needs the rims (description.node_sets) already named. Throws
// tubemesh::Error when the joins make a closed loop or fork (a pipe has no two ends).
void add_pipe_stations(const SweepResult& sweep, const std::vector<RingJoin>& joins, const HybridMesh& mesh,
                       MeshDescription& description);

}  // namespace tubemesh
