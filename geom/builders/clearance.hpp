#pragma once
// How close pipes come to each other, to themselves and to the host boundary, measured on
// centre-line samples. Plain data: the random generator calls it on candidate paths before
// anything is swept.
#include <limits>
#include <vector>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

struct PipeSamples {
    std::vector<Vec3> points;  // along the centre line, evenly spaced by arc length, end to end
    double radius = 0;
};

struct Clearance {
    static constexpr double kNone = std::numeric_limits<double>::infinity();
    // Smallest wall-to-wall distance between two different pipes (0-based ids; -1 when < 2 pipes).
    double pipe_gap = kNone;
    int pipe_a = -1, pipe_b = -1;
    // Smallest wall-to-wall distance between parts of one pipe that are far apart along it
    // (the arms of a U-bend).
    double self_gap = kNone;
    int self_pipe = -1;
    // Smallest distance from a pipe's wall to the host boundary, away from the pipe's ends
    // (further than `end_zone` along the pipe from both ends, where it must meet the boundary).
    double boundary_gap = kNone;
    int boundary_pipe = -1;
};

// Smallest wall-to-wall distance between two pipes.
double pipe_gap(const PipeSamples& a, const PipeSamples& b);

// Sample spacing must be at most the smallest radius for the distances to be meaningful.
Clearance measure_clearance(const std::vector<PipeSamples>& pipes, const HostSpec& host, double end_zone);

}  // namespace tubemesh::geom
