#pragma once
// Geometry the hex rings cannot mesh, found before meshing and told in the user's terms:
// pipe walls that meet (pipes crossing or touching), a pipe wall tangent to a face, and a pipe
// so close to another or to a face that the paper's rules (Dc, Dcb) would cut the ring below
// kThinnestRing of its radius (such a ring takes minutes and millions of elements, and the
// tets between it and the face are slivers). Each is a tubemesh::Error naming the faces or
// pipes, the distance, and what to change. No OpenCASCADE header here.
#include "geom/sizing/sizing.hpp"
#include "geom/sizing/sizing_distances.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// The thinnest ring accepted, as a fraction of the pipe's radius. The block builder's clearance
// checks keep pipes half a diameter apart and a tenth of one from the faces (the random blocks
// 3 and 2 diameters): the room for their rings is 0.0625 r at the least, so none is refused.
inline constexpr double kThinnestRing = 0.05;
// Towards a face with the local ring (SizePlan::local_ring): only the ring's thinnest place is
// that thin, with short steps there, so the gap a pipe a tenth of its radius from a face leaves
// (0.03 r) meshes. Between two pipes kThinnestRing stays: two thin rings face each other there.
inline constexpr double kThinnestLocalRing = 0.02;

// Throws for walls that meet or a wall tangent to a face (from the tube search's rejections of
// a solid with `face_count` faces).
void diagnose_faces(const TubeSearch& tubes, int face_count);

// Throws when the distances (Dc, Dcb) leave room only for a ring thinner than kThinnestRing of
// the radius of the pipe concerned, whatever St the user asked for.
void diagnose_clearances(const TubeSearch& tubes, const SizePlan& plan);

// Throws when a hole that is not a tube comes within kThinnestRing of its radius of a face it
// does not touch: the tets in that gap would be slivers (boundary recovery fails there).
void diagnose_hole_clearances(const std::vector<HoleClearance>& holes);

}  // namespace tubemesh::geom
