#pragma once
// The cross-section a ring stops on inside the solid (TubeData::stops): the plane normal to the
// centre line at that end station. It stands in for a host face wherever the sweep places an
// end's nodes, so a stopped end is swept like an end on a flat host met square.
#include <array>
#include <memory>

#include "engine/geometry/surface_map.hpp"
#include "engine/geometry/tube_data.hpp"

namespace tubemesh::sweep {

// The plane through `centre` normal to `tangent`, its normal turned like a host's outward
// normal (back along the tube at the first end, onwards at the last). face() is 0: no B-rep
// face; it has no trimming loops and no edges.
std::shared_ptr<const SurfaceMap> stop_plane(const Vec3& centre, const Vec3& tangent, bool last_end, double radius);

}  // namespace tubemesh::sweep
