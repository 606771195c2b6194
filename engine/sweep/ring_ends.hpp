#pragma once
// The cross-sections at a tube's two ends: the ring nodes geom placed, moved exactly onto wall
// and host, and the outer nodes on the host face.
#include <optional>
#include <span>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/sweep/centre_line.hpp"
#include "engine/sweep/wall_projection.hpp"

namespace tubemesh::sweep {

// One end's nodes, j-major: entry j·n + k is radial node j of circumferential node k.
struct EndSection {
    std::vector<Vec3> node;     // j = 0: the ring node; j >= 1: on the host face
    std::vector<Uv> uv;         // on the host face
    // Signed distance of each node from the end station's normal plane, along its tangent.
    std::vector<double> depth;
    std::vector<double> angle;   // per k: angle of ring node k about the tangent from the reference
    std::vector<double> radius;  // per k: distance of ring node k from the axis
};

// The ring nodes moved onto the curve where the wall meets the host, each to the nearest point
// of that curve. geom samples the end loop's B-rep edge, whose 3D curve is only an
// approximation of that intersection (within the edge's tolerance: up to 3.6e-5 r measured on
// the builders' blocks), so a node can lie on the host but off the wall. Newton steps on both
// surfaces at once: each moves the node to the nearest point of the line where the two
// tangent planes at its foot points meet, which converges quadratically. Throws
// tubemesh::Error (naming `which` and the node) when a node is farther than radius / 20 from
// that curve or the two surfaces meet tangentially there.
std::vector<Vec3> snap_to_wall_and_host(std::span<const Vec3> ring, const WallProjection& wall,
                                        const SurfaceMap& host, double radius, const char* which);

// Angles, radii and depths of the ring nodes around `station` (node j = 0 of the section).
EndSection ring_section(std::span<const Vec3> ring, const Station& station);

// Turning direction of a ring about the tangent: +1 right-handed, -1 left-handed. Throws
// tubemesh::Error (naming `which`) when the ring does not go once around the axis.
int ring_turn(const EndSection& section, const char* which);

// Fills in radial nodes j = 1..L: node j of column k starts at radius + offsets[j] from the
// axis in the direction of ring node k and moves parallel to the axis onto the host. Lateral
// edges parallel to the axis are the best the end hexes can have: at a wall node the hex's
// lateral edge lies in the wall, so its corner's scaled Jacobian is at most cos α for a host
// met at angle α whatever the outer nodes do, and axis-parallel edges reach that bound.
// `node_scale` (per k, may be empty): column k's offsets are multiplied by it where it is below 1
// (a ring thinner there, RingRoom).
// Throws tubemesh::Error when the host has no foot point or is within 6 degrees of parallel
// to the axis.
void place_on_host(EndSection& section, const Station& station, const SurfaceMap& host,
                   std::span<const double> offsets, double scale, std::span<const double> node_scale = {});

}  // namespace tubemesh::sweep
