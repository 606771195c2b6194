#pragma once
// The pyramid a candidate apex would make, as the criteria see it: corners 0-3 (the front
// quad), apex 4; lateral face f = (f, f+1, apex) and lateral edge k = corner k - apex
// (front_state.hpp checks this against the topology table).
#include <array>

#include "engine/core/types.hpp"
#include "engine/pyramids/geometry.hpp"

namespace tubemesh::pyramids {

struct NewPyramid {
    std::array<index_t, 5> node;  // node[4] == kNoIndex for a new apex
    std::array<Vec3, 5> p;
    std::array<bool, 4> edge_new{true, true, true, true};  // lateral edge k not yet on the front
    std::array<bool, 4> face_new{true, true, true, true};  // lateral face f not yet on the front
    Box box;
    bool has(index_t n) const {
        return n == node[0] || n == node[1] || n == node[2] || n == node[3] || (n != kNoIndex && n == node[4]);
    }
};

}  // namespace tubemesh::pyramids
