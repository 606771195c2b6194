#include "engine/pyramids/visible.hpp"

#include <algorithm>

#include "engine/mesh/edge_key.hpp"

namespace tubemesh::pyramids {

namespace {

// Adds the face when its box comes within the query radius of N.
void add_face(const Front& f, const index_t* nodes, const Vec3* const* p, int size, FaceRole role, Visible& out) {
    Box box = Box::of(*p[0]);
    for (int k = 1; k < size; ++k) box.add(*p[k]);
    if (box_distance2(box, f.ideal) >= f.query_radius * f.query_radius) return;
    VisibleFace& face = out.faces.emplace_back();
    face.size = static_cast<std::uint8_t>(size);
    face.role = role;
    face.box = box;
    face.node = {nodes[0], nodes[1], nodes[2], size == 4 ? nodes[3] : kNoIndex};
    face.p[3] = {};
    for (int k = 0; k < size; ++k) face.p[k] = *p[k];
    face.at_base = face.has(f.node[0]) || face.has(f.node[1]) || face.has(f.node[2]) || face.has(f.node[3]);
}

// The same for faces whose coordinates must be looked up.
void add_face(const FrontState& s, const Front& f, const index_t* nodes, int size, FaceRole role, Visible& out) {
    Vec3 p[4];
    const Vec3* ptr[4];
    for (int k = 0; k < size; ++k) {
        p[k] = s.point(nodes[k]);
        ptr[k] = &p[k];
    }
    add_face(f, nodes, ptr, size, role, out);
}

void collect_faces(const World& w, index_t i, Visible& out) {
    const Front& f = w.fronts[i];
    const FrontState& s = w.state;
    const Vec3* own[4] = {&f.corner[0], &f.corner[1], &f.corner[2], &f.corner[3]};
    add_face(f, f.node.data(), own, 4, FaceRole::Own, out);

    // Fixed faces: boundary triangles still on the front, obstacle quads.
    out.hits.clear();
    w.fixed_faces.query(Box::around(f.ideal, f.query_radius), out.stack, out.hits);
    std::sort(out.hits.begin(), out.hits.end());  // the tree's visiting order is not an order to rely on
    const index_t boundary_count = w.boundary_count;
    for (index_t id : out.hits) {
        if (id < boundary_count) {
            if (!s.boundary_free(id)) continue;
            const Triangle t = s.boundary(id);
            add_face(s, f, t.data(), 3, FaceRole::Front, out);
        } else {
            add_face(s, f, w.obstacles.data() + 4 * (id - boundary_count), 4, FaceRole::Obstacle, out);
        }
    }

    // Neighbour fronts: their quad while pending, their pyramid's free triangles once built.
    // Both lie in the neighbour's reach ball: skip the neighbour when that misses the query ball.
    for (index_t j : w.neighbours.row(i)) {
        const Front& g = w.fronts[j];
        const double apart = f.query_radius + g.reach;
        if (distance2(f.ideal, g.ideal) >= apart * apart) continue;
        if (!s.has_pyramid(j)) {
            const Vec3* quad[4] = {&g.corner[0], &g.corner[1], &g.corner[2], &g.corner[3]};
            add_face(f, g.node.data(), quad, 4, FaceRole::Front, out);
            continue;
        }
        const index_t apex = s.apex(j);
        const Vec3 top = s.point(apex);
        for (int side = 0; side < 4; ++side) {
            if (!s.lateral_free(j, side)) continue;
            // Lateral face `side` (front_state.hpp): base edge side -> side + 1, then the apex.
            const int next = (side + 1) % 4;
            const index_t nodes[3] = {g.node[side], g.node[next], apex};
            const Vec3* p[3] = {&g.corner[side], &g.corner[next], &top};
            add_face(f, nodes, p, 3, FaceRole::Front, out);
        }
    }
}

// Every edge of the visible faces once, sorted by (a, b). Sorted through 64-bit keys: the
// edge records are large to move.
void collect_edges(Visible& out) {
    out.base_ring.clear();
    out.edge_keys.clear();
    for (std::size_t i = 0; i < out.faces.size(); ++i) {
        const VisibleFace& face = out.faces[i];
        if (face.at_base) out.base_ring.insert(out.base_ring.end(), face.node.begin(), face.node.begin() + face.size);
        for (int k = 0; k < face.size; ++k) {
            const index_t u = face.node[k], v = face.node[(k + 1) % face.size];
            const std::uint64_t key = edge_key(u, v);
            out.edge_keys.push_back({key, static_cast<index_t>(4 * i + static_cast<std::size_t>(k))});
        }
    }
    std::sort(out.base_ring.begin(), out.base_ring.end());
    auto near_base = [&](index_t n) { return std::binary_search(out.base_ring.begin(), out.base_ring.end(), n); };
    std::sort(out.edge_keys.begin(), out.edge_keys.end());
    for (std::size_t n = 0; n < out.edge_keys.size(); ++n) {
        const auto [key, slot] = out.edge_keys[n];
        if (n > 0 && out.edge_keys[n - 1].first == key) continue;
        const VisibleFace& face = out.faces[slot / 4];
        const int k = static_cast<int>(slot % 4), l = (k + 1) % face.size;
        VisibleEdge e;
        const bool swap = face.node[l] < face.node[k];
        e.a = swap ? face.node[l] : face.node[k];
        e.b = swap ? face.node[k] : face.node[l];
        e.pa = swap ? face.p[l] : face.p[k];
        e.pb = swap ? face.p[k] : face.p[l];
        e.box = Box::of(e.pa);
        e.box.add(e.pb);
        e.near_base = near_base(e.a) || near_base(e.b);
        out.edges.push_back(e);
    }
}

void collect_nodes(const World& w, index_t i, Visible& out) {
    const Front& f = w.fronts[i];
    const FrontState& s = w.state;
    w.fixed_nodes.within(f.ideal, f.reach, out.kd);
    for (const auto& [id, d2] : out.kd) out.nodes.push_back({id, s.point(id), d2});
    // Apexes are not in the k-d tree; every apex a front can see belongs to a neighbour.
    const double reach2 = f.reach * f.reach;
    for (index_t j : w.neighbours.row(i)) {
        if (!s.has_pyramid(j)) continue;
        const index_t a = s.apex(j);
        const Vec3 p = s.point(a);
        const double d2 = distance2(p, f.ideal);
        if (d2 < reach2) out.nodes.push_back({a, p, d2});
    }
    std::sort(out.nodes.begin(), out.nodes.end(), [](const NearNode& l, const NearNode& r) { return l.id < r.id; });
    out.nodes.erase(std::unique(out.nodes.begin(), out.nodes.end(),
                                [](const NearNode& l, const NearNode& r) { return l.id == r.id; }),
                    out.nodes.end());

    const double rc2 = f.candidate_radius * f.candidate_radius;
    for (const NearNode& n : out.nodes) {
        if (n.d2 >= rc2 || !s.on_front(n.id)) continue;
        if (n.id == f.node[0] || n.id == f.node[1] || n.id == f.node[2] || n.id == f.node[3]) continue;
        out.candidates.push_back(n);
    }
    std::sort(out.candidates.begin(), out.candidates.end(),
              [](const NearNode& l, const NearNode& r) { return l.d2 < r.d2 || (l.d2 == r.d2 && l.id < r.id); });
}

}  // namespace

void gather_visible(const World& w, index_t front, Visible& out) {
    out.faces.clear();
    out.edges.clear();
    out.nodes.clear();
    out.candidates.clear();
    collect_faces(w, front, out);
    collect_edges(out);
    collect_nodes(w, front, out);
}

}  // namespace tubemesh::pyramids
