#pragma once
// The triangulation one face is meshed in: triangles in the face's (u, v) plane whose vertices
// also carry their point on the surface and their target size. Internal to engine/surface.
//
// Conventions. Triangles turn counter-clockwise in uv. Edge i of a triangle is the one across
// from its vertex i, running from vertex i+1 to vertex i+2 (mod 3). adj[3t + i] = 3n + j says
// that edge i of t is edge j of n; kNoIndex on the outer hull. A seam or pole node of the face
// appears as several uv vertices that share one output `node`.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/geometry/surface_map.hpp"

namespace tubemesh::surface {

// Triangle flags.
inline constexpr std::uint8_t kConstrainedEdge0 = 1;  // bit i: edge i is a boundary edge
inline constexpr std::uint8_t kDead = 8;              // slot on the free list
inline constexpr std::uint8_t kInside = 16;           // part of the face (not a hole, not outside)
inline constexpr std::uint8_t kAccepted = 32;         // frontal refinement is done with it

// First fundamental form [[a b][b c]] = J^T J of the surface at a point, J = [dS/du dS/dv]:
// |du|_M is the length in space of a small uv step du.
struct Metric2 {
    double a = 1, b = 0, c = 1;
};

// Everything a vertex carries besides its triangles.
struct VertexData {
    Uv uv;
    Vec3 xyz;
    double size = 0;     // target size there
    index_t node = kNoIndex;  // face-local output node; kNoIndex for the bounding box corners
    Metric2 metric;      // surface metric there
    Vec3 normal{0, 0, 0};  // unit du x dv there; zero at a singular point (pole, apex)
};

// The data of the vertex at uv with derivatives d (metric and normal from d).
VertexData vertex_data(Uv uv, const SurfaceDerivatives& d, const Vec3& xyz, double size, index_t node);

constexpr int next3(int i) { return i == 2 ? 0 : i + 1; }
constexpr int prev3(int i) { return i == 0 ? 2 : i - 1; }

class UvMesh {
public:
    // Vertices.
    std::vector<Uv> uv;
    std::vector<Vec3> xyz;
    std::vector<double> size;    // target size at the vertex
    std::vector<Metric2> metric; // surface metric at the vertex
    std::vector<Vec3> normal;    // unit du x dv at the vertex, zero where singular
    std::vector<index_t> node;   // face-local output node; kNoIndex for the bounding box corners
    std::vector<index_t> vtri;   // one live triangle incident to the vertex

    // Triangles.
    std::vector<index_t> tv;              // 3 per triangle
    std::vector<index_t> adj;             // 3 per triangle
    std::vector<std::uint8_t> flags;      // 1 per triangle
    std::vector<std::uint32_t> gen;       // bumped when a slot is reused: stale heap entries
    std::vector<std::uint32_t> mark;      // traversal marks compared with an epoch
    std::vector<index_t> free_slots;
    std::uint32_t epoch = 0;

    // Keeps the capacity: a mesher reused across faces allocates only when a face is larger
    // than every face before it.
    void clear();

    index_t vertex_count() const { return static_cast<index_t>(uv.size()); }
    index_t slot_count() const { return static_cast<index_t>(flags.size()); }
    index_t add_vertex(const VertexData& v);

    // The triangle (a, b, c) with these positions faces the way the surface does at every
    // corner where its normal is defined (a triangle folded over a pole does not).
    bool faces_out(index_t a, index_t b, index_t c, const Vec3& xa, const Vec3& xb, const Vec3& xc) const;

    // A triangle with no neighbours and no flags; reuses a dead slot when there is one.
    index_t new_triangle(index_t a, index_t b, index_t c);
    void kill(index_t t);

    bool dead(index_t t) const { return flags[t] & kDead; }
    bool inside(index_t t) const { return flags[t] & kInside; }
    bool accepted(index_t t) const { return flags[t] & kAccepted; }
    bool constrained(index_t t, int i) const { return flags[t] & (kConstrainedEdge0 << i); }
    void set_constrained(index_t t, int i, bool on);

    index_t vertex(index_t t, int i) const { return tv[3 * t + i]; }
    index_t neighbor(index_t t, int i) const {
        const index_t a = adj[3 * t + i];
        return a == kNoIndex ? kNoIndex : a / 3;
    }
    int local_index(index_t t, index_t v) const;  // -1 when v is not a vertex of t

    // Makes edge i of t and edge j of n neighbours (n == kNoIndex: hull edge).
    void link(index_t t, int i, index_t n, int j);
    void link(index_t t, int i, index_t packed) { link(t, i, packed == kNoIndex ? kNoIndex : packed / 3, int(packed % 3)); }

    // Starts a traversal: marks equal to the returned value (or value + 1) are this one's.
    std::uint32_t next_epoch();

    // The triangle holding edge a -> b (a then b counter-clockwise in it) and the edge's local
    // index, found by turning around a; {kNoIndex, -1} when there is no such edge.
    std::pair<index_t, int> find_edge(index_t a, index_t b) const;

    // Flips the edge shared by t (its edge i) and its neighbour when the two triangles form a
    // strictly convex quadrilateral in uv and the edge is not constrained. Returns whether it
    // flipped. After the flip, edge 1 of t is the new edge.
    bool flip(index_t t, int i);

    // Flips without the convexity test (the caller checked it).
    void flip_unchecked(index_t t, int i);

    // Removes interior vertex v by merging it into its neighbour ring[k]: the two triangles on
    // edge v-ring[k] go, the others of v's fan take ring[k] in v's place. fan[j] is the triangle
    // (v, ring[j], ring[j+1]) (counter-clockwise around v). The caller checked that the new
    // triangles are valid. Afterwards vtri[v] is kNoIndex: v is gone.
    void collapse_unchecked(index_t v, std::span<const index_t> ring, std::span<const index_t> fan, std::size_t k);
    bool removed(index_t v) const { return vtri[v] == kNoIndex; }
};

}  // namespace tubemesh::surface
