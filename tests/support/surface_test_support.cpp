#include "tests/support/surface_test_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <string>
#include <unordered_map>

#include "engine/predicates/predicates.hpp"

namespace tubemesh::testing {

std::vector<Uv> BoundaryBuilder::cut_side(Uv a, Uv b) const {
    constexpr int samples = 256;
    std::array<double, samples + 1> integral{};
    Vec3 prev = surface_.point(a);
    for (int i = 1; i <= samples; ++i) {
        const double s = double(i) / samples;
        const Vec3 x = surface_.point({a.u + s * (b.u - a.u), a.v + s * (b.v - a.v)});
        const Vec3 mid = 0.5 * (x + prev);
        integral[i] = integral[i - 1] + norm(x - prev) / size_.at(mid);
        prev = x;
    }
    const long n = std::max(1L, std::lround(integral[samples]));
    std::vector<Uv> out;
    int i = 0;
    for (long k = 0; k < n; ++k) {
        const double target = integral[samples] * double(k) / double(n);
        while (i < samples && integral[i + 1] < target) ++i;
        const double span = integral[i + 1] - integral[i];
        const double s = (i + (span > 0 ? (target - integral[i]) / span : 0.0)) / samples;
        out.push_back({a.u + s * (b.u - a.u), a.v + s * (b.v - a.v)});
    }
    return out;
}

index_t BoundaryBuilder::node_at(Uv p) {
    const Vec3 x = surface_.point(p);
    for (index_t k = 0; k < b_.node_count(); ++k)
        if (norm(b_.xyz[k] - x) < 1e-9 * (1 + norm(x))) return k;
    return b_.add_node(b_.node_count(), x);
}

void BoundaryBuilder::add_loop(std::span<const Uv> corners) {
    for (std::size_t i = 0; i < corners.size(); ++i)
        for (const Uv& p : cut_side(corners[i], corners[(i + 1) % corners.size()])) b_.add_loop_point(node_at(p), p);
    b_.close_loop();
}

void BoundaryBuilder::add_polygon(std::span<const Uv> points) {
    for (const Uv& p : points) b_.add_loop_point(node_at(p), p);
    b_.close_loop();
}

std::vector<Uv> uv_polygon(Uv c, double rho, int n, double a0) {
    std::vector<Uv> out;
    for (int k = 0; k < n; ++k) {
        const double a = a0 + 2 * std::numbers::pi * k / n;
        out.push_back({c.u + rho * std::cos(a), c.v + rho * std::sin(a)});
    }
    return out;
}

std::vector<Uv> round_polygon(const SurfaceMap& surface, Uv c, double rho, int n, double a0) {
    // Orthonormal tangent directions t1, t2 at c, mapped back to uv by the inverse tangent map.
    const SurfaceDerivatives d = surface.derivatives(c);
    const double a = dot(d.du, d.du), b = dot(d.du, d.dv), cc = dot(d.dv, d.dv), det = a * cc - b * b;
    const Vec3 t1 = (1 / norm(d.du)) * d.du;
    const Vec3 n_ = cross(d.du, d.dv);
    const Vec3 t2 = (1 / norm(cross(n_, t1))) * cross(n_, t1);
    const auto to_uv = [&](const Vec3& r) {
        const double ru = dot(d.du, r), rv = dot(d.dv, r);
        return Uv{(cc * ru - b * rv) / det, (a * rv - b * ru) / det};
    };
    std::vector<Uv> out;
    for (int k = 0; k < n; ++k) {
        const double t = a0 + 2 * std::numbers::pi * k / n;
        const Uv s = to_uv(std::cos(t) * t1 + std::sin(t) * t2);
        out.push_back({c.u + rho * s.u, c.v + rho * s.v});
    }
    return out;
}

void add_uv_polygon_sources(const SurfaceMap& surface, std::span<const Uv> polygon, std::vector<SizeSource>& out) {
    std::vector<Vec3> x;
    for (const Uv& p : polygon) x.push_back(surface.point(p));
    add_polygon_sources(x, out);
}

namespace {

constexpr double kDeg = 180 / std::numbers::pi;

std::uint64_t key(index_t a, index_t b) { return (std::uint64_t{a} << 32) | b; }

double angle(const Vec3& at, const Vec3& p, const Vec3& q) {
    const Vec3 u = p - at, v = q - at;
    const double c = dot(u, v) / (norm(u) * norm(v));
    return std::acos(std::clamp(c, -1.0, 1.0)) * kDeg;
}

}  // namespace

FaceReport inspect_face(const AnalyticSurface& surface, const surface::FaceBoundary& boundary,
                        const surface::FaceMesh& mesh, const SizeField& size) {
    FaceReport r;
    auto problem = [&](std::string s) {
        if (r.problems.size() < 20) r.problems.push_back(std::move(s));
    };
    if (mesh.boundary_count != boundary.node_count()) problem("boundary count differs");
    for (index_t k = 0; k < boundary.node_count() && k < mesh.xyz.size(); ++k)
        if (mesh.xyz[k].x != boundary.xyz[k].x || mesh.xyz[k].y != boundary.xyz[k].y ||
            mesh.xyz[k].z != boundary.xyz[k].z)
            problem("boundary node " + std::to_string(k) + " moved");

    // uv of every node (a boundary node's first occurrence), for the reference normals.
    std::vector<Uv> uv(mesh.xyz.size());
    for (std::size_t k = boundary.loop_node.size(); k-- > 0;) uv[boundary.loop_node[k]] = boundary.loop_uv[k];
    for (std::size_t k = 0; k < mesh.interior_uv.size(); ++k) uv[mesh.boundary_count + k] = mesh.interior_uv[k];

    std::unordered_map<std::uint64_t, int> directed;
    std::vector<double> tri_size(mesh.triangle_count());
    r.triangles = mesh.triangle_count();
    r.min_angle = 180;
    index_t good = 0;
    for (index_t t = 0; t < mesh.triangle_count(); ++t) {
        const index_t* n = &mesh.triangles[3 * t];
        const Vec3 &a = mesh.xyz[n[0]], &b = mesh.xyz[n[1]], &c = mesh.xyz[n[2]];
        const double angles[3] = {angle(a, b, c), angle(b, c, a), angle(c, a, b)};
        const double lo = std::min({angles[0], angles[1], angles[2]});
        r.min_angle = std::min(r.min_angle, lo);
        r.max_angle = std::max({r.max_angle, angles[0], angles[1], angles[2]});
        if (lo >= 40) ++good;
        const Vec3 normal = cross(b - a, c - a);
        r.area += 0.5 * norm(normal);
        const double lab = norm(b - a), lbc = norm(c - b), lca = norm(a - c);
        r.max_edge = std::max({r.max_edge, lab, lbc, lca});
        tri_size[t] = (lab + lbc + lca) / 3;
        // Against the surface normal at a corner where it is defined (not at a cone's apex).
        Vec3 reference{0, 0, 0};
        for (int i = 0; i < 3 && norm(reference) == 0; ++i) reference = surface.normal(uv[n[i]]);
        if (dot(normal, reference) <= 0) problem("triangle " + std::to_string(t) + " faces inwards");
        for (int i = 0; i < 3; ++i) ++directed[key(n[i], n[(i + 1) % 3])];
    }
    r.fraction_above_40 = r.triangles ? double(good) / r.triangles : 0;
    for (index_t k = 0; k < mesh.xyz.size(); ++k)
        r.max_distance = std::max(r.max_distance, surface.distance(mesh.xyz[k]) / size.at(mesh.xyz[k]));

    std::unordered_map<std::uint64_t, int> segments;
    for (index_t l = 0; l < boundary.loop_count(); ++l) {
        const index_t b0 = boundary.loop_begin[l], b1 = boundary.loop_begin[l + 1];
        for (index_t k = b0; k < b1; ++k) {
            const index_t a = boundary.loop_node[k], b = boundary.loop_node[k + 1 < b1 ? k + 1 : b0];
            if (a == b) continue;
            ++segments[key(std::min(a, b), std::max(a, b))];
            if (!directed.count(key(a, b)) && !directed.count(key(b, a)))
                problem("boundary segment " + std::to_string(a) + "-" + std::to_string(b) + " is not an edge");
        }
    }
    for (const auto& [k, count] : directed) {
        const index_t a = index_t(k >> 32), b = index_t(k & 0xffffffffu);
        if (count > 1) problem("edge " + std::to_string(a) + "-" + std::to_string(b) + " used twice one way");
        // A segment the loops run along twice (a seam, once each way) joins the face to itself.
        const bool twin = directed.count(key(b, a)) > 0;
        const auto seg = segments.find(key(std::min(a, b), std::max(a, b)));
        const int loop_uses = seg == segments.end() ? 0 : seg->second;
        if (!twin && loop_uses != 1) problem("edge " + std::to_string(a) + "-" + std::to_string(b) + " is open");
        if (twin && loop_uses == 1)
            problem("boundary edge " + std::to_string(a) + "-" + std::to_string(b) + " used twice");
    }
    // Neighbour size ratio across interior edges.
    std::unordered_map<std::uint64_t, index_t> owner;
    for (index_t t = 0; t < mesh.triangle_count(); ++t)
        for (int i = 0; i < 3; ++i) owner[key(mesh.triangles[3 * t + i], mesh.triangles[3 * t + (i + 1) % 3])] = t;
    for (const auto& [k, t] : owner) {
        const auto it = owner.find(key(index_t(k & 0xffffffffu), index_t(k >> 32)));
        if (it == owner.end()) continue;
        if (it->second < t) continue;  // each edge once
        const double s = tri_size[t], o = tri_size[it->second];
        const double ratio = std::max(s, o) / std::min(s, o);
        r.max_neighbor_ratio = std::max(r.max_neighbor_ratio, ratio);
        ++r.pairs;
        r.pairs_above_1_4 += ratio > 1.4;
        r.pairs_above_1_5 += ratio > 1.5;
    }
    return r;
}

ClosedReport inspect_closed(const HybridMesh& mesh) {
    ClosedReport r;
    std::vector<std::vector<index_t>> faces;
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
        for (index_t f = 0; f < mesh.face_count(k); ++f) {
            const auto s = mesh.face(k, f);
            faces.emplace_back(s.begin(), s.end());
        }
    r.faces = static_cast<index_t>(faces.size());

    std::map<std::pair<index_t, index_t>, std::pair<int, int>> edges;  // (lo, hi) -> uses lo->hi, hi->lo
    std::vector<std::vector<std::pair<index_t, index_t>>> link(mesh.point_count());  // per vertex: (next, prev)
    std::vector<char> used(mesh.point_count(), 0);
    for (const auto& f : faces) {
        const std::size_t n = f.size();
        for (std::size_t i = 0; i < n; ++i) {
            const index_t a = f[i], b = f[(i + 1) % n];
            auto& e = edges[{std::min(a, b), std::max(a, b)}];
            (a < b ? e.first : e.second)++;
            link[a].emplace_back(b, f[(i + n - 1) % n]);
            used[a] = 1;
        }
    }
    for (const auto& [e, uses] : edges) {
        const int total = uses.first + uses.second;
        if (total == 1) ++r.open_edges;
        if (total > 2) ++r.nonmanifold_edges;
        if (total == 2 && uses.first != 1) ++r.misoriented_edges;
    }
    // A vertex is manifold when its faces form one fan: following "next -> prev" visits all.
    for (index_t v = 0; v < mesh.point_count(); ++v) {
        const auto& l = link[v];
        if (l.empty()) continue;
        std::size_t steps = 0;
        index_t at = l.front().first;
        do {
            const auto it = std::find_if(l.begin(), l.end(), [&](const auto& p) { return p.second == at; });
            if (it == l.end()) break;
            at = it->first;
            ++steps;
        } while (at != l.front().first && steps <= l.size());
        if (steps != l.size() || at != l.front().first) ++r.nonmanifold_vertices;
    }
    long vertices = 0;
    for (char u : used) vertices += u;
    r.euler = vertices - long(edges.size()) + long(faces.size());

    // Triangles (quads split along 0-2) for volume and intersections.
    std::vector<std::array<index_t, 3>> tris;
    for (const auto& f : faces) {
        tris.push_back({f[0], f[1], f[2]});
        if (f.size() == 4) tris.push_back({f[0], f[2], f[3]});
    }
    auto p = [&](index_t i) { return std::array<double, 3>{mesh.x[i], mesh.y[i], mesh.z[i]}; };
    for (const auto& t : tris) {
        const Vec3 a = mesh.point(t[0]), b = mesh.point(t[1]), c = mesh.point(t[2]);
        r.volume += dot(a, cross(b, c)) / 6;
    }
    struct Box {
        double lo[3], hi[3];
        index_t t;
    };
    std::vector<Box> boxes;
    for (index_t t = 0; t < tris.size(); ++t) {
        Box b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}, t};
        for (index_t v : tris[t]) {
            const auto q = p(v);
            for (int d = 0; d < 3; ++d) b.lo[d] = std::min(b.lo[d], q[d]), b.hi[d] = std::max(b.hi[d], q[d]);
        }
        boxes.push_back(b);
    }
    std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.lo[0] < b.lo[0] || (a.lo[0] == b.lo[0] && a.t < b.t); });
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lo[0] <= boxes[i].hi[0]; ++j) {
            const Box &A = boxes[i], &B = boxes[j];
            if (A.lo[1] > B.hi[1] || B.lo[1] > A.hi[1] || A.lo[2] > B.hi[2] || B.lo[2] > A.hi[2]) continue;
            const auto &s = tris[A.t], &o = tris[B.t];
            int shared = 0;
            for (index_t x : s)
                for (index_t y : o) shared += x == y;
            const auto a = p(s[0]), b = p(s[1]), c = p(s[2]), d = p(o[0]), e = p(o[1]), f = p(o[2]);
            const auto contact = predicates::triangle_triangle(a.data(), b.data(), c.data(), d.data(), e.data(), f.data());
            if (contact == predicates::Contact::Crossing) ++r.crossing_pairs;
            if (contact == predicates::Contact::Touching && shared == 0) ++r.touching_pairs;
        }
    return r;
}

void dump_face(const surface::FaceMesh& m, const surface::FaceBoundary& b, const std::string& name) {
    const char* dir = std::getenv("TUBEMESH_SURFACE_DUMP");
    if (dir == nullptr) return;
    FILE* f = std::fopen((std::string(dir) + "/" + name + ".txt").c_str(), "w");
    if (f == nullptr) return;
    for (const Vec3& x : m.xyz) std::fprintf(f, "V %.17g %.17g %.17g\n", x.x, x.y, x.z);
    std::vector<Uv> uv(m.xyz.size());
    for (std::size_t k = b.loop_node.size(); k-- > 0;) uv[b.loop_node[k]] = b.loop_uv[k];
    for (std::size_t k = 0; k < m.interior_uv.size(); ++k) uv[m.boundary_count + k] = m.interior_uv[k];
    for (const Uv& p : uv) std::fprintf(f, "U %.17g %.17g\n", p.u, p.v);
    for (index_t t = 0; t < m.triangle_count(); ++t)
        std::fprintf(f, "T %u %u %u\n", m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]);
    std::fprintf(f, "B %u\n", m.boundary_count);
    std::fclose(f);
}

}  // namespace tubemesh::testing
