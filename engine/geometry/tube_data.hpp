#pragma once
// What geom/ hands the engine about the B-rep: every tube's centre line and end rings, and a
// polyline for every other B-rep edge. Plain data, no OpenCASCADE: the engine can be fed the
// same structs from synthetic input in its tests.
//
// B-rep ids are geom::Model's 1-based face / edge / vertex numbers (0 is never an id), so
// "face_3" in a report is face id 3 here.
#include <array>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"  // Vec3

namespace tubemesh {

// One point of a tube's discretised centre line.
struct TubeStation {
    Vec3 centre;
    Vec3 tangent;  // unit, pointing from ring1's end towards ring2's end
    // Unit, orthogonal to `tangent`: the direction of ring node 0 seen from this station. It
    // follows the wall's own generator line, so a sweep that places node k at angle
    // 2*pi*k/n from it lines up with both rings without accumulating twist.
    Vec3 reference;
    double radius;  // distance from the centre to the wall, measured at this station
};

// How thick the tube's ring may be, per place along it and direction around it (geom's
// clearance to faces and tubes over the room a ring and its pyramids take there). Sample
// (i, d) is the thickness allowed at arc length s[i] from ring1's end, in direction
// cos(2πd/D)·u[i] + sin(2πd/D)·(tangent[i] × u[i]); between samples it is linear in s and
// periodic-linear in the angle (engine/sweep/ring_room.hpp reads it). Empty: no cap anywhere.
struct RingRoom {
    int directions = 0;                 // D
    std::vector<double> s;              // increasing
    std::vector<Vec3> tangent, u;       // unit, u ⊥ tangent, per sample
    std::vector<double> thickness;      // s.size()·D, sample i's D values in a row

    bool empty() const { return s.empty() || directions == 0; }
};

struct TubeData {
    std::vector<index_t> wall_faces;   // the B-rep faces of the tube's lateral surface
    index_t host1 = 0;                 // face holding ring1's loop as a hole (paper: F_n)
    index_t host2 = 0;                 // face holding ring2's loop (F_m); may equal host1
    std::vector<index_t> loop1_edges;  // the B-rep edges of loop E1, in loop order
    std::vector<index_t> loop2_edges;  // and of loop E2

    // Centre line from ring1's end to ring2's end, by arc length; stations.size() - 1 is the
    // number of hex layers. The first and last stations lie in the planes of the end loops
    // when those are planar (the centres of the two loops).
    std::vector<TubeStation> stations;

    // The two end loops, n nodes each, not closed (node 0 is not repeated). Node k of ring1
    // and node k of ring2 sit at the same angle around the axis: node 0 of both lies on one
    // generator line of the wall, and both rings turn the same way, counter-clockwise seen
    // looking along the tangent (right-handed about it). Spacing along each ring is by arc
    // length. Ring nodes are not forced onto the loops' B-rep vertices: nothing outside the
    // swept ring is attached to those.
    std::vector<Vec3> ring1;
    std::vector<Vec3> ring2;

    // Where the ring must be thinner than St (empty: nowhere).
    RingRoom room;

    // stops[e]: end e (0: ring1's, 1: ring2's) lies on a cross-section inside the solid, not on a
    // host face: the ring stops there because no ring worth making fits beyond (walls that meet,
    // a blind end, too little room). That end's station and ring lie in the plane normal to the
    // centre line there (ring node 0 at the end loop's vertex); its loop is the closed edge where
    // the ring's stretch of wall meets the stretch beyond, and its host is the face beyond, which
    // is meshed with triangles that take the ring's wall nodes on that edge. Its end quads are
    // not boundary faces but fronts that get pyramids, like the outer quads.
    std::array<bool, 2> stops{};
    // Per stopped end: the loop edge's curve parameter at ring nodes 0, 1, ..., n - 1 and at node
    // 0 again at the other end of the closed edge's range (n + 1 values, increasing or decreasing),
    // and the edge's one B-rep vertex (at ring node 0).
    std::array<std::vector<double>, 2> stop_params;
    std::array<index_t, 2> stop_vertex{};
};

// How far a curved B-rep edge's chords may stray from it, as a fraction of each chord's own
// length (the local size along the edge). 0.008125 lets a segment turn by 0.065 rad: an inscribed
// polygon then misses 7e-4 of a disk's area. Cut finer by S where S asks for it.
inline constexpr double kDefaultChordal = 0.008125;

// A B-rep edge cut into segments by arc length. Shared by every face that uses the edge, so
// neighbouring face meshes meet node for node.
struct EdgePolyline {
    index_t edge = 0;
    index_t first_vertex = 0;  // B-rep vertex ids at params.front() / params.back(); equal
    index_t last_vertex = 0;   // for a closed edge (whose first point is repeated at the end)
    std::vector<Vec3> points;
    std::vector<double> params;  // the edge's curve parameter at each point, increasing
};

// Everything the engine needs from the geometry besides the SurfaceMaps.
struct DiscreteGeometry {
    double size = 0;        // S: overall mesh size after the sizing rules
    double sweep_size = 0;  // St: thickness of the hex ring and axial spacing of the stations
    std::vector<TubeData> tubes;
    // One polyline per B-rep edge that is neither part of a tube's wall nor one of its end
    // loops, ordered by edge id. Degenerate edges (a cone's apex) are left out.
    std::vector<EdgePolyline> edges;
};

}  // namespace tubemesh
