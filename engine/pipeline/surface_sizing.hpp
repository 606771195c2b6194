#pragma once
// The surface phase's size field (paper §4): S everywhere, finer near the rings' outer
// polygons and where the tets beside a face need it (tet_size_caps.hpp), and the B-rep edges
// cut again where these ask for less than geom's cut at S.
// The pipeline meshes the faces with it; tests that measure the surface against the field the
// mesher was given build it here too, so there is one recipe.
#include <span>
#include <unordered_set>
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "engine/sizing/field/size_field.hpp"

namespace tubemesh {

struct SurfaceSizing {
    std::vector<EdgePolyline> edges;  // every B-rep edge of the model, cut to the field
    SizeFieldOptions options;         // max size S, growth from MeshOptions::size_growth
    std::vector<SizeSource> sources;  // ring polygons, caps, then the cut edges' short segments
};

// The faces a tube's hex ring covers (its wall faces): they get no triangles.
std::unordered_set<index_t> tube_wall_faces(const DiscreteGeometry& g);

// `rings`: the sweep's rings (their ends' outer polygons); `caps`: local sizes from
// tet_size_caps (PipelineResult::surface_size_caps), empty on a first pass. Throws
// tubemesh::Error when S is not positive.
SurfaceSizing surface_sizing(const PipelineInput& in, std::span<const TubeRing> rings, const MeshOptions& options,
                             std::span<const SizeSource> caps);

}  // namespace tubemesh
