#pragma once
// The front must stay a manifold surface. Taking an existing node P can make it touch
// itself at P (two cones meeting at a tip) or along an edge X-P that is already on the
// front; the tet step cannot recover from either. Around each node v of the new pyramid,
// the link of the front faces (the edge b->c opposite v in each face, all faces oriented
// into the unmeshed region) must stay one cycle — or vanish, when v leaves the front.
//
// Only an existing apex can break this (a new apex replaces the base quad by its own cone),
// so the check runs for existing-node candidates only.
#include "engine/pyramids/new_pyramid.hpp"
#include "engine/pyramids/visible.hpp"

namespace tubemesh::pyramids {

// `y` with edge_new / face_new already set (faces it shares with the front leave the front).
bool keeps_front_manifold(const NewPyramid& y, const Visible& vis);

}  // namespace tubemesh::pyramids
