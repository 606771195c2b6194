#include "engine/pyramids/front_link.hpp"

#include <array>
#include <utility>

namespace tubemesh::pyramids {

namespace {

// Link edges a node can have before the check gives up and refuses the candidate.
constexpr int kLinkEdges = 64;

bool is_matched(const VisibleFace& face, const NewPyramid& y) {
    if (face.size != 3) return false;
    for (int f = 0; f < 4; ++f) {
        if (y.face_new[f]) continue;
        const index_t t[3] = {y.node[f], y.node[(f + 1) % 4], y.node[4]};
        int common = 0;
        for (index_t a : t) common += face.has(a);
        if (common == 3) return true;
    }
    return false;
}

bool stays_manifold_at(index_t v, const NewPyramid& y, const Visible& vis) {
    std::array<std::pair<index_t, index_t>, kLinkEdges> link;
    int n = 0;
    auto add = [&](index_t b, index_t c) {
        if (n == kLinkEdges) return false;
        link[n++] = {b, c};
        return true;
    };
    bool room = true;
    vis.for_each_face_of(v, [&](const VisibleFace& face) {
        if (!room || face.role != FaceRole::Front || is_matched(face, y)) return;
        int i = 0;
        while (face.node[i] != v) ++i;
        for (int j = 1; j + 1 < face.size && room; ++j)
            room = add(face.node[(i + j) % face.size], face.node[(i + j + 1) % face.size]);
    });
    if (!room) return false;
    for (int f = 0; f < 4; ++f) {
        if (!y.face_new[f]) continue;
        const std::array<index_t, 3> t{y.node[f], y.node[(f + 1) % 4], y.node[4]};
        for (int i = 0; i < 3; ++i)
            if (t[i] == v && !add(t[(i + 1) % 3], t[(i + 2) % 3])) return false;
    }
    if (n == 0) return true;
    // One chain: no link node starts or ends two edges, and the walk from the start (or, for
    // a cycle, from any edge) visits all n edges. A closed front gives a cycle; a path only
    // occurs where the input front is open (a partial surface, as in unit tests).
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            if (link[a].first == link[b].first || link[a].second == link[b].second) return false;
    auto edge_from = [&](index_t node) {
        for (int a = 0; a < n; ++a)
            if (link[a].first == node) return a;
        return -1;
    };
    auto edge_to = [&](index_t node) {
        for (int a = 0; a < n; ++a)
            if (link[a].second == node) return a;
        return -1;
    };
    int start = 0;
    for (int a = 0; a < n; ++a)
        if (edge_to(link[a].first) < 0) {
            start = a;
            break;
        }
    int at = start, steps = 1;
    for (int next = edge_from(link[at].second); next >= 0 && next != start; next = edge_from(link[at].second)) {
        at = next;
        ++steps;
    }
    return steps == n;
}

}  // namespace

bool keeps_front_manifold(const NewPyramid& y, const Visible& vis) {
    if (y.node[4] == kNoIndex) return true;  // a new apex only replaces the base quad by its cone
    for (index_t v : y.node)
        if (!stays_manifold_at(v, y, vis)) return false;
    return true;
}

}  // namespace tubemesh::pyramids
