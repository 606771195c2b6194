#pragma once
// How much of each pipe's wall is under a hex ring, how thick the ring is, and why it was thinned
// or left out: one record per pipe (a tube, or a group of pipe walls the tube search could not
// take as one, such as pipes that cross), made by geom::prepare_model and completed after the
// sweep (geom/mesh_file.hpp). The text, JSON and HTML reports all read these records.
//
// No OpenCASCADE header here.
#include <string>
#include <vector>

namespace tubemesh::geom {

struct RingCoverage {
    std::vector<int> faces;  // the pipe's wall faces, ascending
    int tube = 0;            // its ring in the mesh (pipe_<tube>, 1-based); 0 without a ring
    double wall_area = 0;
    // The fraction of wall_area under a hex ring, 0 to 1: 1 with a ring along the whole pipe, 0
    // without, between for a ring that stops on a cross-section (TubeInfo::stop).
    double share = 0;
    double thinnest = 0, thickest = 0;  // the ring's thickness anywhere along it; 0 without a ring
    // Why the ring is thinner than the plan's St, or why there is none; empty when neither.
    std::string reason;
    // A ring that stops: the length of centre line under it, from its kept end, and the whole
    // pipe's; both 0 otherwise.
    double ring_length = 0, length = 0;
};

// Wall area under a hex ring over all wall area; 1 when there is no wall.
double ring_share(const std::vector<RingCoverage>& pipes);

// "pipe 1 (faces 6): 100% of wall area 1.88 under a hex ring 0.01 to 0.01 thick", or "faces 9: no
// hex ring on wall area 1.37: <reason>", after one line for the whole: the share of all pipe wall
// under hex rings.
std::vector<std::string> coverage_lines(const std::vector<RingCoverage>& pipes);

}  // namespace tubemesh::geom
