#include "job/cut_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::job {

namespace {

// The view's reach around a pipe, in ring outer radii (r + St): the ring, its pyramids and the
// first few layers of tets, where the tet sizes grade from St towards S.
constexpr double kReachInRingRadii = 4.0;

// The cut plane: a point on it, an orthonormal frame (u, v in the plane, n its normal), and how
// far from the point cells are shown.
struct CutFrame {
    Vec3 centre{0, 0, 0};
    Vec3 u{1, 0, 0}, v{0, 1, 0}, n{0, 0, 1};
    double reach = 0;
};

Vec3 unit(const Vec3& a) { return (1.0 / norm(a)) * a; }

Vec3 station_centre(const HybridMesh& mesh, const TubeRing& ring, index_t station) {
    Vec3 sum{0, 0, 0};
    for (index_t k = 0; k < ring.circumferential; ++k) sum = sum + mesh.point(ring.node(station, 0, k));
    return (1.0 / ring.circumferential) * sum;
}

CutFrame cut_frame(const geom::MeshRun& run) {
    const HybridMesh& mesh = run.result.mesh;
    CutFrame f;
    const std::vector<TubeRing>& rings = run.result.sweep.rings;
    if (!rings.empty() && rings[0].stations >= 2 && rings[0].circumferential > 0) {
        const TubeRing& ring = rings[0];
        const index_t mid = std::clamp<index_t>(ring.stations / 2, 1, ring.stations - 1);
        const Vec3 a = station_centre(mesh, ring, mid - 1);
        const Vec3 b = station_centre(mesh, ring, std::min<index_t>(mid + 1, ring.stations - 1));
        f.centre = station_centre(mesh, ring, mid);
        f.n = unit(b - a);
        const Vec3 wall = mesh.point(ring.node(mid, 0, 0)) - f.centre;
        f.u = unit(wall - dot(wall, f.n) * f.n);
        f.reach = kReachInRingRadii * (norm(wall) + ring.sweep_size);
    } else if (mesh.point_count() > 0) {
        const auto [x0, x1] = std::minmax_element(mesh.x.begin(), mesh.x.end());
        const auto [y0, y1] = std::minmax_element(mesh.y.begin(), mesh.y.end());
        const auto [z0, z1] = std::minmax_element(mesh.z.begin(), mesh.z.end());
        f.centre = {(*x0 + *x1) / 2, (*y0 + *y1) / 2, (*z0 + *z1) / 2};
        f.reach = norm(Vec3{*x1 - *x0, *y1 - *y0, *z1 - *z0});
    }
    f.v = cross(f.n, f.u);
    return f;
}

struct CellRef {
    CellKind kind;
    index_t index;
    double distance2;
};

Vec3 centroid(const HybridMesh& mesh, CellKind kind, index_t c) {
    Vec3 sum{0, 0, 0};
    const auto nodes = mesh.cell(kind, c);
    for (index_t p : nodes) sum = sum + mesh.point(p);
    return (1.0 / nodes.size()) * sum;
}

// The cells behind the plane within the reach of the centre, at most max_cells of them (the
// nearest), in kind then index order.
std::vector<CellRef> cut_cells(const HybridMesh& mesh, const CutFrame& f, std::size_t max_cells) {
    std::vector<CellRef> cells;
    for (CellKind kind : kAllCellKinds)
        for (index_t c = 0; c < mesh.cell_count(kind); ++c) {
            const Vec3 d = centroid(mesh, kind, c) - f.centre;
            if (dot(d, f.n) <= 0 && norm2(d) <= f.reach * f.reach) cells.push_back({kind, c, norm2(d)});
        }
    if (cells.size() > max_cells) {
        std::nth_element(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(max_cells), cells.end(),
                         [](const CellRef& a, const CellRef& b) { return a.distance2 < b.distance2; });
        cells.resize(max_cells);
    }
    std::sort(cells.begin(), cells.end(), [](const CellRef& a, const CellRef& b) {
        return std::pair(a.kind, a.index) < std::pair(b.kind, b.index);
    });
    return cells;
}

double rounded(double x) { return std::round(x * 1e4) / 1e4; }

}  // namespace

nlohmann::json cut_view_json(const geom::MeshRun& run, const std::array<std::vector<double>, kCellKindCount>& primary,
                             std::size_t max_cells) {
    const HybridMesh& mesh = run.result.mesh;
    const CutFrame f = cut_frame(run);
    const std::vector<CellRef> cells = cut_cells(mesh, f, max_cells);
    double scale = 0;
    for (const CellRef& c : cells) scale = std::max(scale, c.distance2);
    scale = scale > 0 ? std::sqrt(scale) : 1.0;

    // Faces by kind and sorted node set: a face two cut cells of one kind share is hidden between
    // them. Each kind keeps its own closed surface, so the pyramids between the ring and the tets
    // show, and hiding one kind in the viewer leaves the others whole.
    std::map<std::array<index_t, 5>, int> seen;
    auto face_key = [&](CellKind kind, index_t c, const LocalFace& lf) {
        const auto nodes = mesh.cell(kind, c);
        std::array<index_t, 5> key{kNoIndex, kNoIndex, kNoIndex, kNoIndex, static_cast<index_t>(kind)};
        for (int i = 0; i < lf.size; ++i) key[i] = nodes[lf.node[i]];
        std::sort(key.begin(), key.begin() + 4);
        return key;
    };
    for (const CellRef& c : cells)
        for (int i = 0; i < topology(c.kind).face_count; ++i) ++seen[face_key(c.kind, c.index, topology(c.kind).face[i])];

    // The worst few of each kind in the cut, worst first.
    constexpr std::size_t kWorstPerKind = 5;
    std::array<std::vector<std::pair<double, std::size_t>>, kCellKindCount> ranked;
    for (std::size_t ci = 0; ci < cells.size(); ++ci)
        ranked[static_cast<int>(cells[ci].kind)].push_back({primary[static_cast<int>(cells[ci].kind)][cells[ci].index], ci});
    nlohmann::json worst = nlohmann::json::array();
    std::vector<char> is_worst(cells.size(), 0);
    for (auto& r : ranked) {
        std::sort(r.begin(), r.end());
        for (std::size_t i = 0; i < std::min(kWorstPerKind, r.size()); ++i) {
            worst.push_back(r[i].second);
            is_worst[r[i].second] = 1;
        }
    }

    std::map<index_t, index_t> local;  // mesh point -> index in "points"
    nlohmann::json points = nlohmann::json::array(), faces = nlohmann::json::array();
    nlohmann::json kinds = nlohmann::json::array(), indices = nlohmann::json::array(), quality = nlohmann::json::array();
    for (std::size_t ci = 0; ci < cells.size(); ++ci) {
        const CellRef& c = cells[ci];
        kinds.push_back(static_cast<int>(c.kind));
        indices.push_back(c.index);
        quality.push_back(rounded(primary[static_cast<int>(c.kind)][c.index]));
        const CellTopology& t = topology(c.kind);
        const auto nodes = mesh.cell(c.kind, c.index);
        for (int i = 0; i < t.face_count; ++i) {
            // A worst cell keeps every face, so its marker has a place even inside its kind's surface.
            if (!is_worst[ci] && seen[face_key(c.kind, c.index, t.face[i])] > 1) continue;
            faces.push_back(ci);
            faces.push_back(t.face[i].size);
            for (int k = 0; k < t.face[i].size; ++k) {
                const index_t p = nodes[t.face[i].node[k]];
                auto [it, added] = local.try_emplace(p, static_cast<index_t>(local.size()));
                if (added) {
                    const Vec3 d = (1.0 / scale) * (mesh.point(p) - f.centre);
                    points.push_back(rounded(dot(d, f.u)));
                    points.push_back(rounded(dot(d, f.v)));
                    points.push_back(rounded(dot(d, f.n)));
                }
                faces.push_back(it->second);
            }
        }
    }
    return {{"scale", scale},
            {"points", points},
            {"cells", {{"kind", kinds}, {"index", indices}, {"quality", quality}}},
            {"faces", faces},
            {"worst", worst}};
}

}  // namespace tubemesh::job
