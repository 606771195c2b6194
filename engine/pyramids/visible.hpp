#pragma once
// What one front looks at (§4 Step 3): the front faces, edges and nodes near its ideal apex,
// gathered with their coordinates into per-thread scratch so that judging a candidate is a
// scan over small flat arrays.
//
// The paper calls visible the triangles and quadrangles *linked to a node* in the search
// sphere. Here a face is visible when it comes within the front's query radius of N, whether
// or not one of its nodes does: a large surface triangle right above a front has no node
// nearby, and it is exactly the face that must stop the apex from leaving the domain.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/pyramids/face_tree.hpp"
#include "engine/pyramids/front_state.hpp"
#include "engine/pyramids/fronts.hpp"
#include "engine/pyramids/geometry.hpp"

namespace tubemesh::pyramids {

enum class FaceRole : std::uint8_t {
    Own,       // the current front's quad
    Front,     // a face of the front: boundary triangle, pending quad, free pyramid triangle;
               // oriented into the unmeshed region
    Obstacle,  // an obstacle quad: not on the front, any orientation
};

struct VisibleFace {
    std::array<index_t, 4> node;
    std::array<Vec3, 4> p;
    std::uint8_t size;  // 3 or 4; a quad is judged as the triangles (0,1,2) and (0,2,3)
    FaceRole role;
    bool at_base;  // the face contains a corner of the current front
    Box box;
    bool has(index_t n) const { return node[0] == n || node[1] == n || node[2] == n || (size == 4 && node[3] == n); }
};

struct VisibleEdge {
    index_t a, b;  // a < b
    Vec3 pa, pb;
    Box box;
    // An end of the edge is a node of a face at the base (one that contains a corner of the
    // current front): the edge is in the base's immediate neighbourhood.
    bool near_base;
};

struct NearNode {
    index_t id;
    Vec3 p;
    double d2;  // squared distance to the ideal apex N
};

// The read-only world every front evaluation sees.
struct World {
    std::span<const Front> fronts;
    const Adjacency& neighbours;
    const FaceTree& fixed_faces;  // ids [0, boundary_count): boundary triangles, then obstacle quads
    index_t boundary_count;
    std::span<const index_t> obstacles;  // 4 per quad
    const FrontState& state;
};

// Per-thread scratch, reused from front to front (no allocation once warm).
struct Visible {
    std::vector<VisibleFace> faces;
    std::vector<VisibleEdge> edges;    // each once, in the order the faces first name them
    std::vector<NearNode> nodes;       // within reach of N: may lie inside a new pyramid (each
                                       // once, but with a focus where a node may repeat)
    std::vector<NearNode> candidates;  // on the front, within the candidate radius, nearest first
                                       // (none with a focus)
    std::vector<index_t> hits, stack;  // fixed faces near N, sorted; the face tree's stack

    // An edge (a, b) of the visible faces (either order).
    bool has_edge(index_t a, index_t b) const;

    // Calls f(face) for each visible face that holds node n, in the order of `faces`. A
    // candidate's checks around its nodes read these, not every face: a front over a finely
    // meshed surface sees thousands.
    template <class F>
    void for_each_face_of(index_t n, F&& f) const {
        if (n >= node_mark.size() || node_mark[n] != stamp) return;
        for (std::int32_t s = node_first[n]; s >= 0; s = slot_next[static_cast<std::size_t>(s)])
            f(faces[static_cast<std::size_t>(s) / 4]);
    }

    // Marks of the last gather, valid where equal to `stamp` (so nothing is cleared between
    // fronts): per node id, the node belongs to a face at the base; per slot of an open-addressing
    // table of edge keys, the slot holds an edge.
    std::uint32_t stamp = 0;
    std::vector<std::uint32_t> base_mark;
    std::vector<std::uint64_t> edge_slot;
    std::vector<std::uint32_t> edge_mark;
    int edge_bits = 0;
    // The lists for for_each_face_of: per node id its first slot (valid where node_mark equals
    // `stamp`), per slot 4·face + corner the next one holding that node (-1: none).
    std::vector<std::uint32_t> node_mark;
    std::vector<std::int32_t> node_first, slot_next;
};

// What one candidate can fail on: only faces and edges whose boxes come within the distance
// threshold of its pyramid's box, and only nodes inside that box, are measured by the criteria
// (criteria.cpp skips everything else by those very box tests), and a new apex reuses no face
// or edge. `all`: no such narrowing.
struct Focus {
    bool all = true;
    Box box;          // the candidate pyramid's
    double margin2 = 0;  // the squared distance threshold
};

// Everything the front's criteria look at, or (with a focus) what one candidate with a new
// apex can fail on: a subset of the former that gives that candidate the same verdict.
void gather_visible(const World& world, index_t front, Visible& out, const Focus& focus = {});

}  // namespace tubemesh::pyramids
