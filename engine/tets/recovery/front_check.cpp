#include "engine/tets/recovery/front_check.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>

#include <tbb/parallel_sort.h>

namespace tubemesh::tets {

namespace {

std::string tri_name(std::span<const index_t> front, std::size_t t) {
    return "front triangle " + std::to_string(t) + " (" + std::to_string(front[3 * t]) + " " +
           std::to_string(front[3 * t + 1]) + " " + std::to_string(front[3 * t + 2]) + ")";
}

}  // namespace

FrontElements check_front(std::span<const index_t> front, index_t point_count) {
    if (front.size() % 3 != 0) throw Error("tet front: the triangle list's length is not a multiple of 3");
    const std::size_t n = front.size() / 3;
    if (n < 4) throw Error("tet front: a closed surface needs at least 4 triangles, got " + std::to_string(n));
    struct HalfEdge {
        index_t lo, hi;
        bool forward;  // runs lo -> hi in its triangle
        index_t tri;
    };
    std::vector<HalfEdge> half;
    half.reserve(3 * n);
    std::vector<std::array<index_t, 4>> sorted_tris(n);
    for (std::size_t t = 0; t < n; ++t) {
        const index_t* v = front.data() + 3 * t;
        for (int k = 0; k < 3; ++k)
            if (v[k] >= point_count)
                throw Error("tet front: " + tri_name(front, t) + " names point " + std::to_string(v[k]) +
                            ", but there are only " + std::to_string(point_count) + " points");
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
            throw Error("tet front: " + tri_name(front, t) + " repeats a point");
        for (int k = 0; k < 3; ++k) {
            const index_t a = v[k], b = v[(k + 1) % 3];
            half.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<index_t>(t)});
        }
        std::array<index_t, 4> s = {v[0], v[1], v[2], static_cast<index_t>(t)};
        std::sort(s.begin(), s.begin() + 3);
        sorted_tris[t] = s;
    }
    tbb::parallel_sort(sorted_tris.begin(), sorted_tris.end());
    for (std::size_t i = 1; i < n; ++i)
        if (std::equal(sorted_tris[i].begin(), sorted_tris[i].begin() + 3, sorted_tris[i - 1].begin()))
            throw Error("tet front: " + tri_name(front, sorted_tris[i - 1][3]) + " and " +
                        tri_name(front, sorted_tris[i][3]) + " have the same points");
    // (lo, hi, tri) is distinct for every half-edge: no triangle repeats a point.
    tbb::parallel_sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::tie(x.lo, x.hi, x.tri) < std::tie(y.lo, y.hi, y.tri);
    });
    FrontElements out;
    out.triangles.resize(n);
    for (std::size_t i = 0; i < n; ++i) out.triangles[i] = {sorted_tris[i][0], sorted_tris[i][1], sorted_tris[i][2]};
    std::vector<std::pair<index_t, index_t>>& edges = out.edges;
    edges.reserve(half.size() / 2);
    for (std::size_t i = 0; i < half.size();) {
        std::size_t j = i;
        while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
        // Built only for an error: a string per front edge would be a serial cost on every run.
        const auto edge = [&] { return "edge " + std::to_string(half[i].lo) + "-" + std::to_string(half[i].hi); };
        if (j - i == 1)
            throw Error("tet front is not closed: " + edge() + " belongs only to " + tri_name(front, half[i].tri));
        if (j - i > 2)
            throw Error("tet front is not manifold: " + edge() + " is shared by " + std::to_string(j - i) +
                        " triangles (" + tri_name(front, half[i].tri) + ", ...)");
        if (half[i].forward == half[i + 1].forward)
            throw Error("tet front is not consistently oriented: " + tri_name(front, half[i].tri) + " and " +
                        tri_name(front, half[i + 1].tri) + " run along " + edge() + " in the same direction");
        edges.emplace_back(half[i].lo, half[i].hi);
        i = j;
    }
    return out;
}

}  // namespace tubemesh::tets
