#pragma once
// The rings into the mesh: ids by prefix sums in tube order, then the nodes, hexes and quads of
// every chunk of stations copied in parallel, so the mesh does not depend on the thread count.
#include <span>
#include <vector>

#include "engine/sweep/ring_quality.hpp"
#include "engine/sweep/station_chunks.hpp"
#include "engine/sweep/sweep.hpp"
#include "engine/sweep/tube_plan.hpp"

namespace tubemesh::sweep {

// Appends the rings (nodes[t] is tube t's node array, station-major) to the mesh and
// describes them. Throws tubemesh::Error, before touching the mesh, when the node count would
// pass 2^32.
SweepResult merge_rings(HybridMesh& mesh, const std::vector<TubeData>& tubes, std::span<const TubePlan> plans,
                        const std::vector<std::vector<Vec3>>& nodes, std::span<const RingQuality> quality,
                        std::span<const StationChunk> chunks, const SweepOptions& options);

}  // namespace tubemesh::sweep
