#include "engine/pyramids/visible.hpp"

#include <algorithm>
#include <cmath>

#include "engine/mesh/edge_key.hpp"

namespace tubemesh::pyramids {

namespace {

// Candidates judged per front, nearest first. A front sees more only where the surface ahead is
// meshed far finer than its quad (a tet hole's wall in a narrow gap): there the farther nodes
// make pyramids as flat as the nearer ones, and judging each against every face ahead made
// the phase quadratic in the surface's fineness.
constexpr std::size_t kMostCandidates = 32;

// Adds the face when its box comes within the query radius of N (and within the focus).
// Inlined: the gather calls it for every face near every front.
[[gnu::always_inline]] inline void add_face(const Front& f, const Focus& focus, const index_t* nodes,
                                            const Vec3* const* p, int size, FaceRole role, Visible& out) {
    Box box = Box::of(*p[0]);
    for (int k = 1; k < size; ++k) box.add(*p[k]);
    if (box_distance2(box, f.ideal) >= f.query_radius * f.query_radius) return;
    if (!focus.all && box_distance2(box, focus.box) > focus.margin2) return;
    VisibleFace face;  // every field set below; emplace_back() would zero it first
    face.size = static_cast<std::uint8_t>(size);
    face.role = role;
    face.box = box;
    face.node = {nodes[0], nodes[1], nodes[2], size == 4 ? nodes[3] : kNoIndex};
    for (int k = 0; k < size; ++k) face.p[k] = *p[k];
    if (size == 3) face.p[3] = {};
    face.at_base = face.has(f.node[0]) || face.has(f.node[1]) || face.has(f.node[2]) || face.has(f.node[3]);
    out.faces.push_back(face);
}

// The same for faces whose coordinates must be looked up.
void add_face(const FrontState& s, const Front& f, const Focus& focus, const index_t* nodes, int size, FaceRole role,
              Visible& out) {
    Vec3 p[4];
    const Vec3* ptr[4];
    for (int k = 0; k < size; ++k) {
        p[k] = s.point(nodes[k]);
        ptr[k] = &p[k];
    }
    add_face(f, focus, nodes, ptr, size, role, out);
}

// The box the fixed faces must overlap: the query ball's, cut to the focus's reach.
Box query_box(const Front& f, const Focus& focus) {
    Box q = Box::around(f.ideal, f.query_radius);
    if (focus.all) return q;
    const double m = std::sqrt(focus.margin2) * (1 + 1e-9);  // never below the true distance
    q.lo = max_each(q.lo, focus.box.lo - Vec3{m, m, m});
    q.hi = min_each(q.hi, focus.box.hi + Vec3{m, m, m});
    return q;
}

// Appends the node to out.nodes when it lies strictly within reach of N (and, with a focus,
// inside its box).
[[gnu::always_inline]] inline void consider_node(const Front& f, const Focus& focus, index_t id, const Vec3& p,
                                                 Visible& out) {
    if (!focus.all && !focus.box.contains(p)) return;
    const double d2 = distance2(f.ideal, p);
    if (d2 < f.reach * f.reach) out.nodes.push_back({id, p, d2});
}

// The nodes of neighbour g (its corners, its apex if built) that consider_node keeps. Every
// apex a front can see belongs to a neighbour.
void consider_nodes_of(const Front& f, const Focus& focus, const FrontState& s, index_t j, const Front& g,
                       Visible& out) {
    for (int k = 0; k < 4; ++k) consider_node(f, focus, g.node[k], g.corner[k], out);
    if (s.has_pyramid(j)) consider_node(f, focus, s.apex(j), s.point(s.apex(j)), out);
}

// With a focus, the neighbours' nodes are collected here, in the same pass over them
// (collect_nodes takes the rest): a neighbour's nodes lie in the box `around` of its corners and
// apex, so none is inside the focus box when that box does not touch it.
void collect_faces(const World& w, index_t i, const Focus& focus, Visible& out) {
    const Front& f = w.fronts[i];
    const FrontState& s = w.state;
    const Vec3* own[4] = {&f.corner[0], &f.corner[1], &f.corner[2], &f.corner[3]};
    add_face(f, focus, f.node.data(), own, 4, FaceRole::Own, out);

    // Fixed faces: boundary triangles still on the front, obstacle quads.
    out.hits.clear();
    w.fixed_faces.query(query_box(f, focus), out.stack, out.hits);
    std::sort(out.hits.begin(), out.hits.end());  // the tree's visiting order is not an order to rely on
    const index_t boundary_count = w.boundary_count;
    for (index_t id : out.hits) {
        if (id < boundary_count) {
            if (!s.boundary_free(id)) continue;
            const Triangle t = s.boundary(id);
            add_face(s, f, focus, t.data(), 3, FaceRole::Front, out);
        } else {
            add_face(s, f, focus, w.obstacles.data() + 4 * (id - boundary_count), 4, FaceRole::Obstacle, out);
        }
    }

    // Neighbour fronts: their quad while pending, their pyramid's free triangles once built.
    // Both lie in the neighbour's reach ball: skip the neighbour when that misses the query ball
    // (or, with a focus, when the box of its corners and apex, which holds them, is too far).
    for (index_t j : w.neighbours.row(i)) {
        const Front& g = w.fronts[j];
        const double apart = f.query_radius + g.reach;
        if (distance2(f.ideal, g.ideal) >= apart * apart) {
            if (!focus.all) consider_nodes_of(f, focus, s, j, g, out);
            continue;
        }
        const bool built = s.has_pyramid(j);
        const index_t apex = built ? s.apex(j) : kNoIndex;
        const Vec3 top = built ? s.point(apex) : Vec3{};
        if (!focus.all) {
            Box around = Box::of(g.corner[0]);
            for (int k = 1; k < 4; ++k) around.add(g.corner[k]);
            if (built) around.add(top);
            const double gap2 = box_distance2(around, focus.box);
            if (gap2 == 0) consider_nodes_of(f, focus, s, j, g, out);
            if (gap2 > focus.margin2) continue;
        }
        if (!built) {
            const Vec3* quad[4] = {&g.corner[0], &g.corner[1], &g.corner[2], &g.corner[3]};
            add_face(f, focus, g.node.data(), quad, 4, FaceRole::Front, out);
            continue;
        }
        for (int side = 0; side < 4; ++side) {
            if (!s.lateral_free(j, side)) continue;
            // Lateral face `side` (front_state.hpp): base edge side -> side + 1, then the apex.
            const int next = (side + 1) % 4;
            const index_t nodes[3] = {g.node[side], g.node[next], apex};
            const Vec3* p[3] = {&g.corner[side], &g.corner[next], &top};
            add_face(f, focus, nodes, p, 3, FaceRole::Front, out);
        }
    }
}

std::size_t edge_hash(std::uint64_t key, int bits) {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> (64 - bits));
}

// Starts a gather: a new stamp, and an edge table with room for `edges` keys at most half full.
void new_stamp(Visible& out, std::size_t edges) {
    if (++out.stamp == 0) {  // wrapped: every old mark could match again
        std::fill(out.base_mark.begin(), out.base_mark.end(), 0);
        std::fill(out.edge_mark.begin(), out.edge_mark.end(), 0);
        std::fill(out.node_mark.begin(), out.node_mark.end(), 0);
        out.stamp = 1;
    }
    if (2 * edges > out.edge_mark.size()) {
        while ((std::size_t{1} << out.edge_bits) < 2 * edges) ++out.edge_bits;
        out.edge_slot.assign(std::size_t{1} << out.edge_bits, 0);
        out.edge_mark.assign(std::size_t{1} << out.edge_bits, 0);
    }
}

// True when the key was not in the table yet (and now is).
bool insert_edge(Visible& out, std::uint64_t key) {
    const std::size_t mask = out.edge_mark.size() - 1;
    for (std::size_t i = edge_hash(key, out.edge_bits);; i = (i + 1) & mask) {
        if (out.edge_mark[i] != out.stamp) {
            out.edge_mark[i] = out.stamp;
            out.edge_slot[i] = key;
            return true;
        }
        if (out.edge_slot[i] == key) return false;
    }
}

void mark_base(Visible& out, index_t n) {
    if (n >= out.base_mark.size()) out.base_mark.resize(std::size_t{n} + 1 + out.base_mark.size() / 2, 0);
    out.base_mark[n] = out.stamp;
}

// The faces of each node, in face order (for_each_face_of): pushed from the last face.
void index_faces(Visible& out) {
    out.slot_next.resize(4 * out.faces.size());
    for (std::size_t i = out.faces.size(); i-- > 0;) {
        const VisibleFace& face = out.faces[i];
        for (int k = 0; k < face.size; ++k) {
            const index_t n = face.node[k];
            if (n >= out.node_mark.size()) {
                const std::size_t size = std::size_t{n} + 1 + out.node_mark.size() / 2;
                out.node_mark.resize(size, 0);
                out.node_first.resize(size, -1);
            }
            const auto slot = static_cast<std::int32_t>(4 * i + static_cast<std::size_t>(k));
            out.slot_next[static_cast<std::size_t>(slot)] = out.node_mark[n] == out.stamp ? out.node_first[n] : -1;
            out.node_mark[n] = out.stamp;
            out.node_first[n] = slot;
        }
    }
}

// Every edge of the visible faces once, with whether it touches the base's neighbourhood.
void collect_edges(Visible& out) {
    std::size_t sides = 0;
    for (const VisibleFace& face : out.faces) sides += face.size;
    new_stamp(out, sides);
    index_faces(out);
    for (const VisibleFace& face : out.faces)
        if (face.at_base)
            for (int k = 0; k < face.size; ++k) mark_base(out, face.node[k]);
    const std::uint32_t* base = out.base_mark.data();
    const std::size_t base_size = out.base_mark.size();
    const std::uint32_t stamp = out.stamp;
    const auto near_base = [&](index_t n) { return n < base_size && base[n] == stamp; };
    for (const VisibleFace& face : out.faces) {
        for (int k = 0; k < face.size; ++k) {
            const int l = k + 1 == face.size ? 0 : k + 1;
            if (!insert_edge(out, edge_key(face.node[k], face.node[l]))) continue;
            const int first = face.node[l] < face.node[k] ? l : k, second = first == k ? l : k;
            VisibleEdge e;
            e.a = face.node[first];
            e.b = face.node[second];
            e.pa = face.p[first];
            e.pb = face.p[second];
            e.box = Box::of(e.pa);
            e.box.add(e.pb);
            e.near_base = near_base(e.a) || near_base(e.b);
            out.edges.push_back(e);
        }
    }
}

// The fixed nodes within reach of N (the front quads' corners and the boundary triangles'
// nodes) and the apexes there. A corner within reach is one of this front's or a neighbour's
// (its own front's reach ball holds it too, so the two balls meet); a boundary node within reach
// lies in the query box, so its triangle is among the face tree's hits. Strictly within the reach
// (and with a focus, inside its box: its triangle then overlaps the focus too).
void collect_nodes(const World& w, index_t i, const Focus& focus, Visible& out) {
    const Front& f = w.fronts[i];
    const FrontState& s = w.state;
    for (int k = 0; k < 4; ++k) consider_node(f, focus, f.node[k], f.corner[k], out);
    for (index_t id : out.hits) {
        if (id >= w.boundary_count) break;  // obstacle quads (sorted after): their nodes are no candidates
        const Triangle t = s.boundary(id);
        for (index_t n : t) consider_node(f, focus, n, s.point(n), out);
    }
    // With a focus only a new apex is judged: the nodes are only tested for lying inside its
    // pyramid, which a repeated node does not change, and there are no candidates. The
    // neighbours' nodes are in already (collect_faces).
    if (!focus.all) return;
    for (index_t j : w.neighbours.row(i)) consider_nodes_of(f, focus, s, j, w.fronts[j], out);
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
    if (out.candidates.size() > kMostCandidates) out.candidates.resize(kMostCandidates);
}

}  // namespace

bool Visible::has_edge(index_t a, index_t b) const {
    if (edge_mark.empty()) return false;
    const std::uint64_t key = edge_key(a, b);
    const std::size_t mask = edge_mark.size() - 1;
    for (std::size_t i = edge_hash(key, edge_bits);; i = (i + 1) & mask) {
        if (edge_mark[i] != stamp) return false;
        if (edge_slot[i] == key) return true;
    }
}

void gather_visible(const World& w, index_t front, Visible& out, const Focus& focus) {
    out.faces.clear();
    out.edges.clear();
    out.nodes.clear();
    out.candidates.clear();
    collect_faces(w, front, focus, out);
    collect_edges(out);
    collect_nodes(w, front, focus, out);
}

}  // namespace tubemesh::pyramids
