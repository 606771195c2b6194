#pragma once
// Synthetic input for the pyramid layer: hex rings (one radial layer) around straight or
// arc-shaped pipes inside a box whose six faces are triangulated conforming to the rings'
// outer polygons where the pipes pass through. The tet region is the box minus the rings'
// outer solids; it is bounded by the box triangles and the rings' outer quads.
//
// The box faces are tensor grids over per-axis grid lines. Where a ring ends on a face, its
// end centre must be a grid node; the 2 x 2 grid cells around it are replaced by a strip of
// 16 triangles from the block's 8 boundary nodes to the ring's 8-gon (so rings have 8
// sides and their end frames are aligned with the face's axes).
#include <array>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::testing {

struct Ring {
    // Per station: centre and a frame (e1, e2) of the cross-section with (e1, e2, tangent)
    // right-handed; outer node k sits at centre + R (cos(k pi/4) e1 + sin(k pi/4) e2).
    std::vector<Vec3> centre, e1, e2;
    double outer_radius = 1.0;
    double pipe_radius = 0.5;
};

// A straight ring along +z from z0 to z1 at (x, y) with `segments` axial steps.
Ring straight_ring(double x, double y, double z0, double z1, int segments, double outer_radius, double pipe_radius);

// A quarter-torus ring in the plane z = zc around the axis (0, 0, zc), centre-line radius
// rho, from the face x = 0 (angle 90 degrees) to the face y = 0 (angle 0).
Ring arc_ring(double rho, double zc, int segments, double outer_radius, double pipe_radius);

struct BoxGrid {
    std::array<std::vector<double>, 3> lines;  // per axis, ascending, first = 0
};

struct RingScene {
    HybridMesh mesh;
    std::vector<index_t> front_quads;         // the rings' outer quads, normal away from the ring
    std::vector<index_t> boundary_triangles;  // box faces, normal out of the box
    std::vector<index_t> obstacle_quads;      // the rings' end quads
    index_t pyramid_region = 0;
    double box_volume = 0;
    double ring_volume = 0;  // volume enclosed by the rings' outer quads and their end 8-gons
};

// Throws std::runtime_error when a ring end is not at a grid node of a box face.
RingScene build_ring_scene(const BoxGrid& box, const std::vector<Ring>& rings);

// Evenly spaced values from a to b with `steps` steps, b included.
std::vector<double> spaced(double a, double b, int steps);

}  // namespace tubemesh::testing
