#pragma once
// Tube recognition, topological half (paper §3.1, rules 2-6): groups of faces whose boundary
// is exactly two hole loops of other faces, short enough for the length rule. The geometric
// half (does the group close smoothly around an axis?) is in tubes_wall.hpp.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geom/model/model.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

struct LoopEdge {
    int edge = 0;
    bool forward = true;  // the wire runs along the edge's parameter
};

// One wire of a face, in wire order (BRepTools_WireExplorer).
struct FaceWire {
    std::vector<LoopEdge> edges;
    bool outer = false;
};

// Adjacency the rules walk, as ids. Built once per model.
struct TopologyIndex {
    explicit TopologyIndex(const Model& model);

    const Model& model;
    std::vector<std::vector<int>> edge_faces;       // [edge id] -> distinct face ids around it
    std::vector<std::vector<FaceWire>> face_wires;  // [face id] -> its wires
    std::vector<char> in_hole;                      // [edge id] -> edge lies in a non-outer wire
    std::vector<char> degenerate;                   // [edge id] -> BRep_Tool::Degenerated
    std::vector<double> edge_length;                // [edge id]
};

// A hole of a host face: one non-outer wire.
struct HoleLoop {
    int host = 0;
    int wire = 0;  // index into face_wires[host]
    std::vector<LoopEdge> edges;
    double length = 0;
};

struct TubeCandidate {
    std::vector<int> faces;         // ascending
    std::array<HoleLoop, 2> loops;  // E1, E2 (see find_tubes for the order)
};

struct CandidateSearch {
    std::vector<TubeCandidate> candidates;
    std::vector<TubeRejection> rejected;
};

// Every group reached from some hole loop, accepted or with the rule it broke. A group seen
// from both of its loops is reported once.
CandidateSearch find_tube_candidates(const TopologyIndex& index, const TubeOptions& options);

// The candidate as a tube, or nullopt with the reason in `why` when its faces do not close
// smoothly around an axis from one loop to the other (find_tubes' geometric rules).
std::optional<TubeInfo> candidate_tube(const TopologyIndex& index, const TubeCandidate& candidate, std::string& why);

// The candidate a recognised tube came from, rebuilt from its ids (for discretisation, which
// gets TubeInfo, not candidates). Throws tubemesh::Error when the ids do not fit the model.
TubeCandidate candidate_of(const TopologyIndex& index, const TubeInfo& tube);

}  // namespace tubemesh::geom
