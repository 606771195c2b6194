#include "engine/mesh/surface_groups.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh {

namespace {

constexpr double kFlatAngle = 1e-6;

template <class F>
void each_triangle(const HybridMesh& mesh, F&& f) {
    const FaceBlock& tris = mesh.block(FaceKind::Tri);
    for (std::size_t t = 0; t < tris.group.size(); ++t)
        f(tris.group[t], mesh.point(tris.nodes[3 * t]), mesh.point(tris.nodes[3 * t + 1]),
          mesh.point(tris.nodes[3 * t + 2]));
    const FaceBlock& quads = mesh.block(FaceKind::Quad);
    for (std::size_t q = 0; q < quads.group.size(); ++q) {
        const index_t* n = &quads.nodes[4 * q];
        f(quads.group[q], mesh.point(n[0]), mesh.point(n[1]), mesh.point(n[2]));
        f(quads.group[q], mesh.point(n[0]), mesh.point(n[2]), mesh.point(n[3]));
    }
}

}  // namespace

std::vector<SurfaceGroupGeometry> surface_group_geometry(const HybridMesh& mesh) {
    std::vector<SurfaceGroupGeometry> g(mesh.surface_group_names.size());
    std::vector<Vec3> normal_sum(g.size(), Vec3{0, 0, 0}), moment(g.size(), Vec3{0, 0, 0});
    each_triangle(mesh, [&](index_t id, const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 n2 = cross(b - a, c - a);  // twice the area, outward
        const double area = 0.5 * norm(n2);
        g[id].area += area;
        moment[id] = moment[id] + (area / 3.0) * (a + b + c);
        normal_sum[id] = normal_sum[id] + 0.5 * n2;
    });
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
        for (index_t id : mesh.block(k).group) ++g[id].faces;
    for (std::size_t id = 0; id < g.size(); ++id) {
        if (g[id].area > 0) g[id].centroid = (1.0 / g[id].area) * moment[id];
        const double length = norm(normal_sum[id]);
        // Divided, not multiplied by 1 / length: a group in an axis plane gets the unit axis
        // exactly, whatever its triangles.
        const Vec3& sum = normal_sum[id];
        if (length > 0) g[id].normal = Vec3{sum.x / length, sum.y / length, sum.z / length};
        g[id].flat = g[id].faces > 0 && length > 0;
    }
    each_triangle(mesh, [&](index_t id, const Vec3& a, const Vec3& b, const Vec3& c) {
        if (!g[id].flat) return;
        const Vec3 n2 = cross(b - a, c - a);
        const double length = norm(n2);
        if (length == 0) return;  // a degenerate triangle says nothing about flatness
        if (norm(cross(n2, g[id].normal)) > kFlatAngle * length || dot(n2, g[id].normal) <= 0) g[id].flat = false;
    });
    return g;
}

std::vector<std::vector<index_t>> surface_group_nodes(const HybridMesh& mesh) {
    std::vector<std::vector<index_t>> nodes(mesh.surface_group_names.size());
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad}) {
        const FaceBlock& b = mesh.block(k);
        const std::size_t size = static_cast<std::size_t>(face_size(k));
        for (std::size_t f = 0; f < b.group.size(); ++f)
            nodes[b.group[f]].insert(nodes[b.group[f]].end(), b.nodes.begin() + size * f,
                                     b.nodes.begin() + size * (f + 1));
    }
    for (auto& n : nodes) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    return nodes;
}

std::vector<SharedNodes> shared_group_nodes(const HybridMesh& mesh) {
    // (node, group) pairs sorted by node: a node in several groups is a run of pairs.
    const std::vector<std::vector<index_t>> nodes = surface_group_nodes(mesh);
    std::vector<std::pair<index_t, index_t>> membership;
    for (index_t g = 0; g < nodes.size(); ++g)
        for (index_t n : nodes[g]) membership.emplace_back(n, g);
    std::sort(membership.begin(), membership.end());
    std::map<std::pair<index_t, index_t>, std::vector<index_t>> shared;
    for (std::size_t i = 0; i < membership.size();) {
        std::size_t j = i;
        while (j < membership.size() && membership[j].first == membership[i].first) ++j;
        for (std::size_t a = i; a < j; ++a)
            for (std::size_t b = a + 1; b < j; ++b)
                shared[{membership[a].second, membership[b].second}].push_back(membership[i].first);
        i = j;
    }
    std::vector<SharedNodes> out;
    for (auto& [groups, n] : shared) out.push_back({groups.first, groups.second, std::move(n)});
    return out;
}

}  // namespace tubemesh
