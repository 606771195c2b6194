#include "tests/support/mesh_io_samples.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::testing {

namespace {

// Sign of the orientation of points a, b, c, d of m (the one tet_volume of vec3_ops).
double orient(const HybridMesh& m, index_t a, index_t b, index_t c, index_t d) {
    return tet_volume(m.point(a), m.point(b), m.point(c), m.point(d));
}

struct Grid {
    int n;
    index_t id(int i, int j, int k) const { return static_cast<index_t>((k * (n + 1) + j) * (n + 1) + i); }
};

// Grid indices of every point (-1 for cube centres), to find faces on the outer box.
using GridIndex = std::array<int, 3>;

void add_boundary_faces(HybridMesh& m, const std::vector<GridIndex>& where, int n, CellKind kind, index_t cell,
                        const std::array<index_t, 6>& groups) {
    const CellTopology& topo = topology(kind);
    const auto nodes = m.cell(kind, cell);
    for (int f = 0; f < topo.face_count; ++f) {
        const LocalFace& face = topo.face[f];
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                bool on = true;
                for (int k = 0; k < face.size; ++k) on = on && where[nodes[face.node[k]]][axis] == side * n;
                if (!on) continue;
                std::array<index_t, 4> f4{};
                for (int k = 0; k < face.size; ++k) f4[k] = nodes[face.node[k]];
                const index_t g = groups[2 * axis + side];
                if (face.size == 3)
                    m.add_face(FaceKind::Tri, std::span<const index_t>(f4.data(), 3), g);
                else
                    m.add_face(FaceKind::Quad, f4, g);
            }
    }
}

}  // namespace

HybridMesh mixed_grid(int n) {
    HybridMesh m;
    const Grid grid{n};
    std::vector<GridIndex> where;
    const double h = 1.0 / n;
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                // Jitter makes coordinates that need all 17 digits in text.
                const double e = 0.01 * h * std::sin(1.7 * i + 2.3 * j + 3.1 * k);
                m.add_point(i * h + e, j * h - e, k * h + 0.5 * e);
                where.push_back({i, j, k});
            }
    std::array<index_t, 3> layer{};
    for (int r = 0; r < 3; ++r) layer[r] = m.region_id("layer_" + std::to_string(r));
    m.region_id("unused");
    std::array<index_t, 6> side{};
    const char* side_names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
    for (int s = 0; s < 6; ++s) side[s] = m.surface_group_id(side_names[s]);
    m.surface_group_id("unused_group");

    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                std::array<index_t, 8> hex{grid.id(i, j, k),         grid.id(i + 1, j, k),
                                           grid.id(i + 1, j + 1, k), grid.id(i, j + 1, k),
                                           grid.id(i, j, k + 1),     grid.id(i + 1, j, k + 1),
                                           grid.id(i + 1, j + 1, k + 1), grid.id(i, j + 1, k + 1)};
                const index_t region = layer[(k * 3) / n];
                const int type = (i + 2 * j + k) % 3;
                if (type == 0) {
                    const index_t c = m.add_cell(CellKind::Hex, hex, region);
                    add_boundary_faces(m, where, n, CellKind::Hex, c, side);
                } else if (type == 1) {
                    const Vec3 a = m.point(hex[0]), b = m.point(hex[6]);
                    const index_t apex = m.add_point((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2);
                    where.push_back({-1, -1, -1});
                    for (int f = 0; f < 6; ++f) {
                        // Hex faces point out of the cube; a pyramid base points to its apex.
                        const LocalFace& face = kHexTopology.face[f];
                        std::array<index_t, 5> pyr{hex[face.node[3]], hex[face.node[2]], hex[face.node[1]],
                                                   hex[face.node[0]], apex};
                        const index_t c = m.add_cell(CellKind::Pyramid, pyr, region);
                        add_boundary_faces(m, where, n, CellKind::Pyramid, c, side);
                    }
                } else {
                    // Six tets around the diagonal 0-6, one per axis order.
                    const int steps[6][2] = {{1, 2}, {1, 5}, {3, 2}, {3, 7}, {4, 5}, {4, 7}};
                    for (const auto& s : steps) {
                        std::array<index_t, 4> t{hex[0], hex[s[0]], hex[s[1]], hex[6]};
                        if (orient(m, t[0], t[1], t[2], t[3]) < 0) std::swap(t[0], t[1]);
                        const index_t c = m.add_cell(CellKind::Tet, t, region);
                        add_boundary_faces(m, where, n, CellKind::Tet, c, side);
                    }
                }
            }
    return m;
}

std::string first_difference(const HybridMesh& a, const HybridMesh& b) {
    if (a.x != b.x) return "x";
    if (a.y != b.y) return "y";
    if (a.z != b.z) return "z";
    for (CellKind k : kAllCellKinds) {
        if (a.block(k).nodes != b.block(k).nodes) return std::string(topology(k).name) + " nodes";
        if (a.block(k).region != b.block(k).region) return std::string(topology(k).name) + " regions";
    }
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad}) {
        const std::string name = k == FaceKind::Tri ? "triangle" : "quad";
        if (a.block(k).nodes != b.block(k).nodes) return name + " nodes";
        if (a.block(k).group != b.block(k).group) return name + " groups";
    }
    if (a.region_names != b.region_names) return "region names";
    if (a.surface_group_names != b.surface_group_names) return "surface group names";
    return "";
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path.string());
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

int entry_count(const std::filesystem::path& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
    return n;
}

}  // namespace tubemesh::testing
