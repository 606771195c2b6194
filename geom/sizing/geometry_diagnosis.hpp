#pragma once
// Pipes that get no hex ring, found before meshing and told in the user's terms: pipe walls that
// meet (pipes crossing or touching, a T-junction), a pipe wall tangent to a face, a pipe so close
// to another or to a face that the thickest ring there is under the thinnest worth making (such a
// ring takes minutes and millions of elements), a bend tighter than the pipe. Such a pipe's wall
// is meshed like any hole that is no tube (curvature-sized triangles, tetrahedra) while the other
// pipes keep their rings: a valid solid is never refused for its pipes. Each finding names the
// pipe, its faces, why, and what would give it a ring. A boundary that touches itself along a
// line has no conforming mesh at all, and is refused. No OpenCASCADE header here.
#include <string>
#include <vector>

#include "geom/sizing/sizing.hpp"
#include "geom/sizing/sizing_distances.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// The thinnest ring a pipe keeps, as a fraction of its radius. With one St for every ring a thin
// ring thins them all and the element count grows with 1/St^2 (0.074 r took 25 s and 790 k
// elements on a 4 x 3 x 2 block), so a pipe that leaves less room than kThinnestSharedRing loses
// its ring instead; with rings thinned locally (SizingOptions::local_ring) only kThinnestRing.
inline constexpr double kThinnestRing = 0.05;
inline constexpr double kThinnestSharedRing = 0.1;
inline double thinnest_ring(bool local_ring) { return local_ring ? kThinnestRing : kThinnestSharedRing; }
// Towards a face a locally thinned ring is that thin only at its thinnest place, with short steps
// there, so a pipe a tenth of its radius from a face (a gap of 0.03 r for the ring) keeps its
// ring. Between two pipes thinnest_ring stays: two thin rings face each other there.
inline constexpr double kThinnestLocalRingToFace = 0.02;
inline double thinnest_ring_to_face(bool local_ring) {
    return local_ring ? kThinnestLocalRingToFace : kThinnestSharedRing;
}

// A group of faces meshed with triangles and tets where a pipe would have had a hex ring.
struct RingDrop {
    std::vector<int> faces;  // the pipe's wall faces, ascending
    double radius = 0;       // the pipe's (smallest) radius; 0 when the search did not measure it
    double length = 0;       // of its centre line; 0 when not measured
    std::string reason;      // short, for the reports: "walls meet", "0.1 r from face 4", ...
    std::string warning;     // one line: the pipe, its faces, why, and what would give it a ring
    // Too little room at a spot (a face or a pipe too near there), not along the whole pipe: its
    // ring may stop before the spot instead (prepare.hpp).
    bool spot = false;
    // `faces` are ids of the model after this many of prepare_model's splits where rings stop
    // (PreparedModel::splits); 0: the given model's.
    int splits = 0;
};

// Throws tubemesh::Error when an edge of the solid bounds more than two faces: its boundary
// touches itself along that edge (a pipe wall tangent to a face or to another pipe along a line),
// where no conforming mesh exists, since every boundary edge of one lies on exactly two boundary
// faces. The message names the edge and its faces and what to change.
void refuse_self_contact(const Model& model);

// The rejected groups that are pipes without a ring: walls that meet, walls that overlap (a
// crease along the axis), a wall tangent to a face (from the tube search's rejections of a solid
// with `face_count` faces).
std::vector<RingDrop> walls_without_ring(const TubeSearch& tubes, int face_count);

// Moves the tubes that end on a pipe wall (another tube's, or one of `dropped`: the branch of a
// T-junction, whose end loop has no plane for the ring to end on) from tubes.tubes to `dropped`.
void drop_branches(TubeSearch& tubes, std::vector<RingDrop>& dropped);

// The tube (index into tubes.tubes) whose ring the distances (Dc, Dcb) or a bend leave the least
// room for, when that room is under `thinnest` of its radius (`thinnest_to_face` towards a face),
// whatever St the user asked for;
// -1 when every ring fits. `drop` says why. Of two pipes too close to each other, the one with
// the smaller wall goes, unless only the other would leave room for the ring of the one kept.
int tube_without_room(const TubeSearch& tubes, const SizePlan& plan, double thinnest, double thinnest_to_face,
                      RingDrop& drop);

// A hole that is not a tube within kThinnestRing of its radius of a face it does not touch: the
// tets in that gap are flat. One warning line each; `cause` gets the narrowest such gap in a few
// words ("a gap too narrow for sound tets (the hole of faces 9 passes 0 from face 6, ...)"), for
// the quality warning; empty when none.
std::vector<std::string> narrow_gap_warnings(const std::vector<HoleClearance>& holes, std::string& cause);

}  // namespace tubemesh::geom
