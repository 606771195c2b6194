#pragma once
// What the files and the report say about a mesh beyond the mesh store: the model's length
// unit, each surface group's CAD surface kind and a name that says where it is, and named node
// sets (each pipe's inlet and outlet rims), and surfaces seen from one region (an assembly
// solid's top). The pipeline adds the rims, geom the rest.
#include <string>
#include <vector>

#include "engine/core/types.hpp"

namespace tubemesh {

struct SurfaceGroupInfo {
    std::string surface_kind;  // the B-rep face's surface: "plane", "cylinder", "B-spline", ...
    std::string alias;         // where it is: the CAD file's or a built block's name ("top", ...); may be empty
};

struct NamedNodeSet {
    std::string name;            // e.g. "pipe_1_inlet"
    std::vector<index_t> nodes;  // ascending
};

// The boundary of one region seen from that region's cells: an assembly solid's top, whose
// faces may be a joint with the solid above (where an element set must take the faces of
// this region's elements, not of its neighbour's).
struct RegionSurface {
    std::string name;             // e.g. "block_1_2_top"
    index_t region = 0;           // index into HybridMesh::region_names
    std::vector<index_t> groups;  // the surface groups it is made of, ascending
};

struct MeshDescription {
    std::string length_unit;  // "metre", "millimetre", "model units", ...; empty when not known
    std::vector<SurfaceGroupInfo> surface_groups;  // by surface group id; missing ids: unknown
    std::vector<NamedNodeSet> node_sets;
    std::vector<RegionSurface> region_surfaces;

    const SurfaceGroupInfo* group(std::size_t id) const {
        return id < surface_groups.size() ? &surface_groups[id] : nullptr;
    }
};

}  // namespace tubemesh
