#pragma once
// The part of the run that changes: which fronts carry a pyramid and with which apex, the
// apexes created so far, the set of front triangles (boundary triangles and free pyramid
// triangles) and, per node, how many front faces use it.
//
// A front triangle is found through its nodes: a boundary triangle through the rows of its
// smallest node, a pyramid's lateral face through the fronts that have one of its nodes as a
// corner (two of its three nodes are). Those rows are built once, so a commit writes a few
// per-front entries and nothing is hashed; a new apex is in no triangle yet and needs no search.
//
// Changed only between batches, by one thread (add_pyramid, remove_pyramid); read by many
// threads while a batch is evaluated. New apexes are staged here and reach the mesh only
// when the run has succeeded, so a drawback that deletes a pyramid leaves no orphan point
// and a failed run leaves the mesh untouched.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/pyramids/fronts.hpp"

namespace tubemesh::pyramids {

// How a front got its apex (PyramidStats): 0 none, then these, then kHowTryBase + k - 1 for
// the k-th try node, then kHowMovedTryBase + k - 1 for the k-th try node moved off the faces
// (candidates.hpp).
enum : std::uint8_t {
    kHowNone = 0,
    kHowIdeal = 1,
    kHowExisting = 2,
    kHowExistingRelaxed = 3,
    kHowWide = 4,
    kHowTryBase = 5,
    kHowMovedTryBase = kHowTryBase + 8
};

// A front's accepted candidate. node == kNoIndex: a new apex at `position`. When none was
// accepted, `refusal` says why the last new node tried (ideal or try node) was refused.
struct Choice {
    bool found = false;
    index_t node = kNoIndex;
    Vec3 position{};
    std::uint8_t how = kHowNone;
    Verdict refusal = Verdict::Accepted;
};

// Who owns a front triangle: lateral face f (0..3) of front j's pyramid is 4 j + f; input
// boundary triangle b is kBoundaryOwner | b.
inline constexpr index_t kBoundaryOwner = 0x80000000u;

using Triangle = std::array<index_t, 3>;

// The pyramid's lateral faces, out of the pyramid, from the topology table (faces 1-4):
// face f runs along base edge f -> f+1 and up to the apex 4. The module indexes lateral faces
// and edges by base corner on the strength of this check.
constexpr bool lateral_faces_follow_base_edges() {
    for (int f = 0; f < 4; ++f) {
        const LocalFace& face = kPyramidTopology.face[static_cast<std::size_t>(f) + 1];
        if (face.size != 3 || face.node[0] != f || face.node[1] != (f + 1) % 4 || face.node[2] != 4) return false;
    }
    return kPyramidTopology.node_count == 5;
}
static_assert(lateral_faces_follow_base_edges(), "pyramids/ assumes lateral face f = (f, f+1, apex)");

// True when the two triangles have the same nodes in the same cyclic order.
inline bool same_orientation(const Triangle& s, const Triangle& t) {
    for (int r = 0; r < 3; ++r)
        if (s[0] == t[r] && s[1] == t[(r + 1) % 3] && s[2] == t[(r + 2) % 3]) return true;
    return false;
}

class FrontState {
public:
    // Boundary triangles as the input gives them (normal out of the tet region). Throws
    // tubemesh::Error when one is listed twice.
    FrontState(const HybridMesh& mesh, std::span<const Front> fronts, std::span<const index_t> boundary_triangles);

    index_t mesh_points() const { return mesh_points_; }
    Vec3 point(index_t node) const { return node < mesh_points_ ? mesh_.point(node) : apexes_[node - mesh_points_]; }
    // The node bounds the unmeshed region: some front face (boundary triangle, pending front
    // quad or free pyramid triangle) uses it.
    bool on_front(index_t node) const { return live_[node] > 0; }

    bool has_pyramid(index_t front) const { return apex_[front] != kNoIndex; }
    index_t apex(index_t front) const { return apex_[front]; }
    std::uint8_t how(index_t front) const { return how_[front]; }

    // Lateral face f of front j's pyramid, oriented out of the pyramid (into the tet region).
    Triangle lateral(index_t front, int f) const;
    // The face is on the front: not shared with another pyramid, not covering a boundary
    // triangle. Only meaningful while the front has a pyramid.
    bool lateral_free(index_t front, int f) const { return partner_[front][f] == kNoIndex; }
    // Boundary triangle b not covered by a pyramid face.
    bool boundary_free(index_t b) const { return boundary_partner_[b] == kNoIndex; }
    // Boundary triangle b oriented like the front (into the unmeshed region).
    Triangle boundary(index_t b) const { return boundary_[b]; }

    // Owner of the front triangle with these three nodes (any order), or kNoIndex.
    index_t find(const Triangle& t) const;
    // The front triangle of an owner, oriented into the unmeshed region.
    Triangle triangle(index_t owner) const;

    void add_pyramid(index_t front, const Choice& choice);
    void remove_pyramid(index_t front);

    const std::vector<Vec3>& apexes() const { return apexes_; }
    index_t apex_uses(index_t staged) const { return apex_uses_[staged]; }

private:
    struct Key {
        index_t a, b, c;  // sorted
        bool operator==(const Key&) const = default;
    };
    static Key key(const Triangle& t);
    // The owner of the front triangle with key k, but none of front `skip`'s faces.
    index_t find(const Key& k, index_t skip) const;
    void set_partner(index_t owner, index_t partner);
    void count(const Triangle& t, int delta);

    const HybridMesh& mesh_;
    std::span<const Front> fronts_;
    index_t mesh_points_;
    std::vector<Vec3> apexes_;
    std::vector<index_t> apex_uses_;
    std::vector<index_t> live_;  // per node: mesh points, then staged apexes
    std::vector<index_t> apex_;
    std::vector<std::uint8_t> how_;
    std::vector<std::array<index_t, 4>> partner_;  // per front and lateral face: owner it cancels
    std::vector<Triangle> boundary_;
    std::vector<index_t> boundary_partner_;
    Adjacency boundary_at_;  // mesh node -> boundary triangles whose smallest node it is
    Adjacency corner_of_;    // mesh node -> fronts with it as a corner
};

}  // namespace tubemesh::pyramids
