#pragma once
// What the files and the report say about a mesh beyond the mesh store: the model's length
// unit, each surface group's CAD surface kind and a name that says where it is, and named node
// sets (each pipe's inlet and outlet rims), and each pipe's stations for the water network. The
// pipeline adds the rims and the stations, geom the rest.
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/vec3.hpp"

namespace tubemesh {

struct SurfaceGroupInfo {
    std::string surface_kind;  // the B-rep face's surface: "plane", "cylinder", "B-spline", ...
    std::string alias;         // where it is on a built block ("top", "upstream", ...); may be empty
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

struct MeshDescription {
    std::string length_unit;  // "metre", "millimetre", "model units", ...; empty when not known
    std::vector<SurfaceGroupInfo> surface_groups;  // by surface group id; missing ids: unknown
    std::vector<NamedNodeSet> node_sets;
    std::vector<PipeStations> pipes;  // in pipe order (pipe_1, pipe_2, ...)

    const SurfaceGroupInfo* group(std::size_t id) const {
        return id < surface_groups.size() ? &surface_groups[id] : nullptr;
    }
};

}  // namespace tubemesh
