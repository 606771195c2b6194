#pragma once
// The validity and suitability criteria of §4 Step 4 for one candidate apex, judged against
// what the front sees. Returns the first criterion that fails, cheapest checks first.
//
// Reading of the paper made precise here:
//  * "distance between the new edges and visible edges": a new edge X-P fails only where it
//    comes nearer to a front edge than both the threshold and its own base corner X, and
//    edges touching the faces at the base are not measured (criteria.cpp says why). Judged
//    literally, every candidate on rings whose quads are longer than about twice their width
//    would fail on their own short edges, and the end pyramids of a ring on the triangles of
//    the host face under them, whatever their apex.
//  * "distance between N and visible faces": faces that contain the candidate node itself
//    are skipped (distance zero by construction); the front's own quad is kept, which keeps
//    an existing node from being accepted almost in the base plane.
//  * quads (pending fronts, obstacles) are judged as the triangles (0,1,2) and (0,2,3).
//  * "the new element does not contain any existing node": strictly inside its four lateral
//    faces and above its base; a node on a face is caught by its edges meeting that face.
//  * not in the paper: a candidate whose pyramid scaled Jacobian is below the front's quality
//    floor (fronts.hpp) is refused, so that a permissive relaxed pass cannot take a sliver;
//    and an existing node that would make the front touch itself (front_link.hpp).
//  * every yes/no incidence question is decided with the exact predicates; a contact at a
//    shared node is allowed, any other contact (touching included) is a failure.
#include <cstdint>

#include "engine/pyramids/build_pyramids.hpp"
#include "engine/pyramids/front_state.hpp"
#include "engine/pyramids/fronts.hpp"
#include "engine/pyramids/visible.hpp"

namespace tubemesh::pyramids {

struct Candidate {
    index_t id;  // kNoIndex: a new node (the ideal node or a try node)
    Vec3 p;
};

// The criteria's numbers at one relaxation Rate (1 for the normal pass).
struct Thresholds {
    double cos_max_angle;  // cos(max_angle / Rate), 0 when that reaches 90 degrees
    double min_distance2;  // (distance_factor · h · Rate)^2
    static Thresholds at(const Front& f, const PyramidOptions& opt, double rate);
};

Verdict judge(const Front& f, const Candidate& c, const Thresholds& t, const Visible& vis, const FrontState& state);

// A try node that is too close to a face, moved off the nearest such face to the distance
// threshold — along the face's normal to that distance in front of its plane (front faces
// are oriented into the unmeshed region), straight away from it for an obstacle — and again
// while another face is too close, at most kMoveSteps times. Not in the paper, whose try
// nodes stay on the normal line: where a host face leans over a ring's end quad (an oblique
// or curved end, where the last station meets the host at an acute angle) every point of
// that line down to M is too close to the host, or even beyond it, while a point tilted away
// from it is a good apex. True when p was moved and is now clear of every face and inside
// the front's reach (so batches stay independent, fronts.hpp); false otherwise, p then
// meaningless. The moved node still has to pass judge (angle, quality floor, edges,
// intersections) like any other candidate.
inline constexpr int kMoveSteps = 4;
bool move_off_faces(const Front& f, const Thresholds& t, const Visible& vis, Vec3& p);

}  // namespace tubemesh::pyramids
