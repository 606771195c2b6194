#pragma once
// Mesh sizes (paper §2): S, the overall size, and St, the sweep size (thickness of the hex
// ring around each tube and axial spacing of its layers), from the user or from defaults,
// then cut down by the paper's three rules in the paper's order:
//   1. St > 1.4 Dcb  ->  St = 1.4 Dcb
//   2. St > 0.6 Dc   ->  St = 0.6 Dc
//   3. St > 0.8 Rc   ->  St = 0.8 Rc
// with Dcb the smallest distance from a tube's wall to a boundary face other than its hosts
// (and other tubes' walls), Dc the smallest distance between two tubes' walls, Rc the
// smallest radius of curvature of a centre line.
//
// The paper also sets S = 1.3 St with every rule. We do not: its own examples contradict it
// (Table 1's second example keeps tets of about S = 1.1 around holes whose bends cut St far
// below 1.1 / 1.3), and tying S to a cut St multiplies the element count by orders of
// magnitude (bench/results/tuning-notes.md). S only follows St where it was derived from it:
// the default S below is recomputed from the final St. Cutting St therefore never raises S
// above the user's value.
//
// The rules alone still let a ring collide: St = 1.4 Dcb is thicker than the gap it sits in.
// So three guards follow, each cutting St to 95% of its limit when broken, with a ring of
// thickness St and the room its pyramid layer needs in front of it, 2.2 St: the paper's
// criteria (try nodes down to Rate 0.9^5) need about 1.2 h there, h the outer quads' mean
// edge, which reaches 1.8 St (their axial edges reach 1.9 St):
//   boundary: St + 2.2 St < Dcb       (ring and pyramids stay clear of non-host faces)
//   rings:    2 St + 2.2 St < Dc      (both rings and a pyramid layer fit between them)
//   bend:     r_max + St < Rc             (the ring does not fold on the inside of a bend)
//
// Defaults: St = the smallest tube diameter (2 r_min): with n ring nodes chosen so the
// ring's quads are about square, that gives 8 nodes around a tube. S = the bounding-box
// diagonal / 25, but at least 1.3 St. Without tubes St is 0 and only S is planned. With a
// sweep share (the economy preset) the default St is that share of S instead (S first), at most
// 12.5 tube radii: a thicker ring of 4 nodes has hexes over Cond 4.
//
// No OpenCASCADE header here: the CLI prints plans through this file.
#include <string>
#include <vector>

#include "geom/model/model.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

// Room the pyramid layer needs in front of a ring, over St: about 1.2 h (measured on pipes side
// by side and over a face with the pyramid step's default criteria), h the outer quads' mean
// edge, which reaches 1.8 St. So a ring and its pyramids take (1 + kPyramidRoom) St towards a
// face and two of them (2 + kPyramidRoom) St between two tubes.
inline constexpr double kPyramidRoom = 2.2;
inline constexpr double kFaceRoom = 1 + kPyramidRoom;
inline constexpr double kTubeRoom = 2 + kPyramidRoom;
// A guard cuts St to this fraction of its limit, so the apex does not just touch.
inline constexpr double kGuardMargin = 0.95;

struct SizingOptions {
    double size = 0;        // S; 0 chooses the default
    double sweep_size = 0;  // St; 0 chooses the default
    // > 0: the default St is this share of S (given or default), at most 12.5 smallest tube radii,
    // instead of the smallest tube diameter; the rules and guards still cut it. A given St wins.
    double sweep_share = 0;
    // Rules 1 and 2 and the boundary and rings guards are left to the ring's local thickness
    // (ring_room.hpp): St stays, and each ring thins only where a face or a tube is near. Off
    // (default): the paper's one St, cut for the closest place of all. Not yet the default:
    // two rings facing each other across a thin gap can leave their pyramids no room.
    bool local_ring = false;
};

struct SizeChange {
    std::string rule;  // "1: St > 1.4 Dcb", ..., "guard: boundary", "guard: rings", "guard: bend"
    double old_sweep_size = 0, new_sweep_size = 0;
    double old_size = 0, new_size = 0;
    std::string reason;  // names the tubes and faces involved and the distances
};

struct SizePlan {
    double size = 0;          // S, after the rules and guards
    double sweep_size = 0;    // St, after the rules and guards
    double initial_size = 0;  // S and St before any change: the user's or the defaults
    double initial_sweep_size = 0;
    std::string size_source;  // where the initial S came from: "user" or the default's formula
    std::string sweep_source;
    double dc = 0;                      // +inf with fewer than two tubes
    double dcb = 0;                     // +inf when no face other than the hosts exists
    int dc_tube_a = -1, dc_tube_b = -1; // 0-based tubes attaining dc
    int dcb_tube = -1, dcb_face = 0;    // the tube attaining dcb and the face it is near
    double rc = 0;                      // +inf when every tube is straight
    std::vector<SizeChange> changes;    // in the order they were made
    // The rings thin locally (SizingOptions::local_ring): discretize fills TubeData::room.
    bool local_ring = false;
    // The largest St the rules and guards accept here (what they cut an unbounded St to) and
    // the change that set it; +inf and empty without tubes or when nothing bounds St.
    double largest_sweep_size = 0;
    std::string largest_sweep_limit;
    std::vector<std::string> warnings;  // what no size can fix (a bend tighter than the tube)
};

// "rule 1: St > 1.4 Dcb", "guard: boundary": a SizeChange::rule as a sentence names it.
std::string sizing_rule_name(const std::string& rule);

// Throws tubemesh::Error for a non-positive or non-finite size given by the user.
SizePlan plan_sizes(const Model& model, const std::vector<TubeInfo>& tubes, const SizingOptions& options = {});

}  // namespace tubemesh::geom
