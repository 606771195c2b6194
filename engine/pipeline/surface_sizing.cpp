#include "engine/pipeline/surface_sizing.hpp"

#include <unordered_map>
#include <unordered_set>

#include "engine/sizing/curvature_sizes.hpp"
#include "engine/surface/face_boundaries.hpp"

namespace tubemesh {

std::unordered_set<index_t> tube_wall_faces(const DiscreteGeometry& g) {
    std::unordered_set<index_t> walls;
    for (const TubeData& t : g.tubes) walls.insert(t.wall_faces.begin(), t.wall_faces.end());
    return walls;
}

SurfaceSizing surface_sizing(const PipelineInput& in, std::span<const TubeRing> rings, const MeshOptions& options,
                             std::span<const SizeSource> caps) {
    const DiscreteGeometry& g = in.geometry;
    if (!(g.size > 0)) throw Error("the overall mesh size S must be positive to mesh the surfaces");
    const std::unordered_set<index_t> walls = tube_wall_faces(g);

    SurfaceSizing out;
    out.options.max_size = g.size;
    out.options.growth = options.size_growth;
    std::vector<SizeSource> ring_sources;
    for (const TubeRing& ring : rings)
        for (const RingEnd& end : ring.ends) add_polygon_sources(end.outer_xyz, ring_sources);
    ring_sources.insert(ring_sources.end(), caps.begin(), caps.end());
    ring_sources.insert(ring_sources.end(), in.gap_sizes.begin(), in.gap_sizes.end());
    for (const PipelineFace& f : in.faces)
        if (!(f.tube_wall || walls.count(f.id)))
            if (const SurfaceMap* map = in.surfaces(f.id)) add_curvature_sources(*map, g.size, ring_sources);
    // geom cut the B-rep edges at S (finer where they curve); where the rings or caps ask for less they
    // are cut again, on the first face (in id order) that uses them. Then the edges' own short
    // segments (curved or short edges) become sources too, so the faces grade from them.
    std::unordered_map<index_t, surface::EdgeOnFace> edge_faces;
    for (const PipelineFace& f : in.faces)
        if (!(f.tube_wall || walls.count(f.id)))
            if (const SurfaceMap* map = in.surfaces(f.id)) surface::add_edge_faces(*map, edge_faces);
    out.sources = ring_sources;
    const SizeField ring_field(out.options, std::move(ring_sources));
    out.edges = surface::follow_size_field(g.edges, edge_faces, ring_field);
    surface::add_short_edge_sources(out.edges, ring_field, out.sources);
    return out;
}

}  // namespace tubemesh
