#pragma once
// What the files and the report say about a mesh beyond the mesh store: the model's length
// unit, each surface group's CAD surface kind and a name that says where it is, and named node
// sets (each pipe's inlet and outlet rims), surfaces seen from one region (an assembly solid's
// top), and each pipe's stations for the water network. The pipeline adds the rims and the
// stations, geom the rest.
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/core/vec3.hpp"

namespace tubemesh {

struct SurfaceGroupInfo {
    std::string surface_kind;  // the B-rep face's surface: "plane", "cylinder", "B-spline", ...
    std::string alias;         // where it is: the CAD file's or a built block's name ("top", ...); may be empty
};

struct NamedNodeSet {
    std::string name;            // e.g. "pipe_1_inlet"
    std::vector<index_t> nodes;  // ascending
};

// One pipe's wall as the sweep laid it out, station after station from its first end (the rim
// "<name>_inlet") to its second; a joined pipe's rings follow each other, their shared cross-section
// once. A wall face lies between two consecutive stations: the station -> wall face map the water
// network's *FILM lines need (engine/io/inp_network.hpp).
struct PipeStations {
    std::string name;                 // the wall's surface group, "pipe_<k>"
    index_t circumferential = 0;      // wall nodes per station
    std::vector<Vec3> centres;        // the centre-line point of each station
    std::vector<index_t> wall_nodes;  // circumferential per station, in station order
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
    std::vector<PipeStations> pipes;  // in pipe order (pipe_1, pipe_2, ...)
    std::vector<RegionSurface> region_surfaces;

    const SurfaceGroupInfo* group(std::size_t id) const {
        return id < surface_groups.size() ? &surface_groups[id] : nullptr;
    }
};

}  // namespace tubemesh
