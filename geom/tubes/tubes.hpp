#pragma once
// Recognition of tubular holes (paper §3.1) in a geom::Model.
//
// A tube is a group of faces (one face with a seam, or several where a CAD system split the
// lateral surface around or along the axis) whose boundary is exactly two closed loops E1 and
// E2, each a complete hole (non-outer wire) of a face outside the group, F_n and F_m (possibly
// the same face), each shorter than `max_loop_ratio` times the mean edge length of its host's
// outer loop. The group must close around the axis smoothly: no planar faces, no crease along
// the axis, and a generator line of the wall must lead from E1 to E2. Blind holes, pockets
// (one loop), slots (planar, creased) and the ends of a pipe solid (the loop is an outer wire)
// are not tubes.
//
// No OpenCASCADE header here: the CLI reports tubes through this file.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

struct TubeOptions {
    // Paper §3.1: a loop is a tube end only if its length is below this fraction of the mean
    // edge length of its host face's outer loop.
    double max_loop_ratio = 0.2;
    // Largest angle between the normals of two wall faces across an edge running along the
    // axis; beyond it the wall has a crease and the group is a slot, not a tube.
    double max_crease_deg = 10.0;
};

struct TubeInfo {
    std::vector<int> faces;                 // wall faces, ascending ids
    std::array<std::vector<int>, 2> loops;  // edge ids of E1 and E2, in loop order
    std::array<int, 2> hosts{};             // host face of E1 and of E2
    std::array<double, 2> loop_lengths{};   // length of E1 and of E2
    double radius_min = 0;                  // distance from the centre line to the wall, smallest ...
    double radius_max = 0;                  // ... and largest (equal for a circular section)
    double length = 0;                      // of the centre line
    // Smallest radius of curvature of the centre line; +infinity for a straight tube. Kinks
    // where wall faces meet at an angle (a mitred joint) are not curvature: see max_kink_deg.
    double min_curvature_radius = 0;
    double max_kink_deg = 0;  // largest turn of the centre line across a face boundary
    // Points of the centre line from E1's end to E2's, about one per diameter and denser in
    // bends (no chord more than 1% of the radius off the axis). Sizing measures distances on it.
    std::vector<Vec3> centre_line;
    // Set when the ring stops on a cross-section inside the solid (geom/tubes/ring_stop.hpp):
    // `faces`, loops[1], hosts[1] and centre_line are then the stretch under the ring, up to the
    // closed edge loops[1] = {edge}; the wall beyond (`beyond`, ending on `loop` of `host`) is
    // meshed with triangles and tets. A pipe with a spot in the middle keeps a ring on each side:
    // two tubes, each beyond its own cut; `beyond` is then the wall between the cuts only.
    struct Stop {
        int edge = 0;
        std::vector<int> beyond;  // ascending
        std::vector<int> wall;    // the whole pipe's wall faces, ascending
        std::vector<int> loop;
        int host = 0;
        double loop_length = 0;
        double length = 0;  // of the whole centre line
        std::vector<Vec3> centre_line;  // the whole one
        std::string reason;  // why: the spot beyond, for the reports
        // The wall meets another pipe's beyond the cut (geom/sizing/junction.hpp): no whole tube
        // runs on, so `wall`, `length` and `centre_line` are the pipe's and the stretch is
        // discretised as it is.
        bool stretch_only = false;
    };
    std::optional<Stop> stop;
};

// A group of faces that looked like a tube but broke a rule, for `tubemesh inspect`.
struct TubeRejection {
    std::vector<int> faces;
    std::string reason;
    int loops = -1;  // the loops bounding the group, when the search got as far as counting them
    // Curved faces only, two loops, but two of them meet along the axis at an angle: the hole
    // of pipes that overlap (or a slot milled with curved sides). It gets tets, not a ring.
    bool crease = false;
    // A tube that lost its ring (geometry_diagnosis.hpp) keeps the radius the search measured;
    // 0: a hole's radius is read from its cylinder and torus faces.
    double radius = 0;
};

struct TubeSearch {
    std::vector<TubeInfo> tubes;  // ordered by their smallest face id
    std::vector<TubeRejection> rejected;
};

// E1 is the loop whose host face has the smaller id (the smaller first edge id if both loops
// share a host), so the result does not depend on which loop the search met first.
TubeSearch find_tubes(const Model& model, const TubeOptions& options = {});

}  // namespace tubemesh::geom
