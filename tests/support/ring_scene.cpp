#include "tests/support/ring_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::testing {

namespace {

constexpr int kSides = 8;

double coord(const Vec3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
double det(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

class Builder {
public:
    RingScene scene;

    index_t node(const Vec3& p) {
        const std::array<double, 3> key{p.x, p.y, p.z};
        const auto it = nodes_.find(key);
        if (it != nodes_.end()) return it->second;
        const index_t id = scene.mesh.add_point(p.x, p.y, p.z);
        nodes_.emplace(key, id);
        return id;
    }

    // Outward normal of a box face is +/- e_axis; triangles are emitted with that normal.
    void triangle(index_t a, index_t b, index_t c, const Vec3& outward) {
        const Vec3 pa = scene.mesh.point(a), pb = scene.mesh.point(b), pc = scene.mesh.point(c);
        if (dot(cross(pb - pa, pc - pa), outward) < 0) std::swap(b, c);
        scene.boundary_triangles.insert(scene.boundary_triangles.end(), {a, b, c});
    }

private:
    std::map<std::array<double, 3>, index_t> nodes_;
};

struct RingNodes {
    std::vector<std::array<index_t, kSides>> outer, inner;  // per station
};

RingNodes add_ring(Builder& b, const Ring& ring, index_t hex_region) {
    RingNodes rn;
    const std::size_t stations = ring.centre.size();
    for (std::size_t s = 0; s < stations; ++s) {
        std::array<index_t, kSides> o{}, in{};
        for (int k = 0; k < kSides; ++k) {
            const double t = 2.0 * std::numbers::pi * k / kSides, c = std::cos(t), si = std::sin(t);
            auto at = [&](double r) {
                const Vec3& m = ring.centre[s];
                return Vec3{m.x + r * (c * ring.e1[s].x + si * ring.e2[s].x),
                            m.y + r * (c * ring.e1[s].y + si * ring.e2[s].y),
                            m.z + r * (c * ring.e1[s].z + si * ring.e2[s].z)};
            };
            o[k] = b.node(at(ring.outer_radius));
            in[k] = b.node(at(ring.pipe_radius));
        }
        rn.outer.push_back(o);
        rn.inner.push_back(in);
    }
    HybridMesh& m = b.scene.mesh;
    for (std::size_t s = 0; s + 1 < stations; ++s) {
        for (int k = 0; k < kSides; ++k) {
            const int l = (k + 1) % kSides;
            const auto &I0 = rn.inner[s], &O0 = rn.outer[s], &I1 = rn.inner[s + 1], &O1 = rn.outer[s + 1];
            const std::array<index_t, 8> hex{I0[k], O0[k], O0[l], I0[l], I1[k], O1[k], O1[l], I1[l]};
            m.add_cell(CellKind::Hex, hex, hex_region);
            b.scene.front_quads.insert(b.scene.front_quads.end(), {O0[k], O0[l], O1[l], O1[k]});
        }
    }
    for (std::size_t s : {std::size_t{0}, stations - 1})
        for (int k = 0; k < kSides; ++k) {
            const int l = (k + 1) % kSides;
            b.scene.obstacle_quads.insert(b.scene.obstacle_quads.end(),
                                          {rn.inner[s][k], rn.inner[s][l], rn.outer[s][l], rn.outer[s][k]});
        }
    return rn;
}

// Volume of the solid bounded by the ring's outer quads (split along 0-2, as the pyramid
// bases are) and its two end 8-gons, by the divergence theorem.
double ring_volume(const HybridMesh& m, const RingNodes& rn) {
    double six_v = 0;
    auto tri = [&](index_t a, index_t b, index_t c) { six_v += det(m.point(a), m.point(b), m.point(c)); };
    const std::size_t stations = rn.outer.size();
    for (std::size_t s = 0; s + 1 < stations; ++s)
        for (int k = 0; k < kSides; ++k) {
            const int l = (k + 1) % kSides;
            const index_t q[4] = {rn.outer[s][k], rn.outer[s][l], rn.outer[s + 1][l], rn.outer[s + 1][k]};
            tri(q[0], q[1], q[2]);
            tri(q[0], q[2], q[3]);
        }
    for (int k = 1; k + 1 < kSides; ++k) {
        tri(rn.outer[0][0], rn.outer[0][k + 1], rn.outer[0][k]);  // normal -tangent
        tri(rn.outer[stations - 1][0], rn.outer[stations - 1][k], rn.outer[stations - 1][k + 1]);
    }
    return six_v / 6.0;
}

struct Hole {
    int iu, iv;
    std::array<index_t, kSides> polygon;
};

std::size_t line_index(const std::vector<double>& lines, double v) {
    const auto it = std::find(lines.begin(), lines.end(), v);
    if (it == lines.end() || it == lines.begin() || it + 1 == lines.end())
        throw std::runtime_error("ring end is not at an interior grid node of a box face");
    return static_cast<std::size_t>(it - lines.begin());
}

void add_face(Builder& b, const BoxGrid& g, int axis, bool high, const std::vector<Hole>& holes) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const auto& lu = g.lines[u];
    const auto& lv = g.lines[v];
    const double fixed = high ? g.lines[axis].back() : g.lines[axis].front();
    Vec3 outward{0, 0, 0};
    (axis == 0 ? outward.x : axis == 1 ? outward.y : outward.z) = high ? 1.0 : -1.0;
    auto at = [&](std::size_t i, std::size_t j) {
        double c[3];
        c[axis] = fixed;
        c[u] = lu[i];
        c[v] = lv[j];
        return b.node({c[0], c[1], c[2]});
    };
    auto in_hole = [&](std::size_t i, std::size_t j) {
        for (const Hole& h : holes)
            if ((i + 1 == static_cast<std::size_t>(h.iu) || i == static_cast<std::size_t>(h.iu)) &&
                (j + 1 == static_cast<std::size_t>(h.iv) || j == static_cast<std::size_t>(h.iv)))
                return true;
        return false;
    };
    for (std::size_t i = 0; i + 1 < lu.size(); ++i)
        for (std::size_t j = 0; j + 1 < lv.size(); ++j) {
            if (in_hole(i, j)) continue;
            b.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), outward);
            b.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), outward);
        }
    for (const Hole& h : holes) {
        // The block's 8 boundary nodes counter-clockwise in (u, v) from angle 0.
        const int du[kSides] = {1, 1, 0, -1, -1, -1, 0, 1}, dv[kSides] = {0, 1, 1, 1, 0, -1, -1, -1};
        std::array<index_t, kSides> block{};
        for (int k = 0; k < kSides; ++k)
            block[k] = at(static_cast<std::size_t>(h.iu + du[k]), static_cast<std::size_t>(h.iv + dv[k]));
        // The ring's 8-gon sorted by angle in (u, v), starting nearest angle 0.
        const double cu = lu[h.iu], cv = lv[h.iv];
        std::array<std::pair<double, index_t>, kSides> by_angle{};
        for (int k = 0; k < kSides; ++k) {
            const Vec3 p = b.scene.mesh.point(h.polygon[k]);
            double a = std::atan2(coord(p, v) - cv, coord(p, u) - cu);
            if (a < -std::numbers::pi / kSides) a += 2 * std::numbers::pi;
            by_angle[k] = {a, h.polygon[k]};
        }
        std::sort(by_angle.begin(), by_angle.end());
        for (int k = 0; k < kSides; ++k) {
            const int l = (k + 1) % kSides;
            b.triangle(by_angle[k].second, block[k], block[l], outward);
            b.triangle(by_angle[k].second, block[l], by_angle[l].second, outward);
        }
    }
}

}  // namespace

std::vector<double> spaced(double a, double b, int steps) {
    std::vector<double> v;
    for (int i = 0; i <= steps; ++i) v.push_back(i == steps ? b : a + (b - a) * i / steps);
    return v;
}

Ring straight_ring(double x, double y, double z0, double z1, int segments, double outer_radius, double pipe_radius) {
    Ring r;
    r.outer_radius = outer_radius;
    r.pipe_radius = pipe_radius;
    for (double z : spaced(z0, z1, segments)) {
        r.centre.push_back({x, y, z});
        r.e1.push_back({1, 0, 0});
        r.e2.push_back({0, 1, 0});
    }
    return r;
}

Ring arc_ring(double rho, double zc, int segments, double outer_radius, double pipe_radius) {
    Ring r;
    r.outer_radius = outer_radius;
    r.pipe_radius = pipe_radius;
    for (int s = 0; s <= segments; ++s) {
        // From 90 degrees down to 0; the ends exactly on the faces x = 0 and y = 0.
        const double phi = std::numbers::pi / 2 * (segments - s) / segments;
        const double c = s == segments ? 1.0 : s == 0 ? 0.0 : std::cos(phi);
        const double sn = s == segments ? 0.0 : s == 0 ? 1.0 : std::sin(phi);
        r.centre.push_back({rho * c, rho * sn, zc});
        r.e1.push_back({c, sn, 0});  // radial; with e2 = z the tangent is (sin, -cos, 0)
        r.e2.push_back({0, 0, 1});
    }
    return r;
}

RingScene build_ring_scene(const BoxGrid& box, const std::vector<Ring>& rings) {
    Builder b;
    HybridMesh& m = b.scene.mesh;
    const index_t hex_region = m.region_id("hex_ring");
    b.scene.pyramid_region = m.region_id("pyramids");
    std::array<std::array<std::vector<Hole>, 2>, 3> holes;  // per axis, low/high side
    for (const Ring& ring : rings) {
        const RingNodes rn = add_ring(b, ring, hex_region);
        b.scene.ring_volume += ring_volume(m, rn);
        for (std::size_t s : {std::size_t{0}, ring.centre.size() - 1}) {
            const Vec3& c = ring.centre[s];
            int axis = -1;
            bool high = false;
            for (int a = 0; a < 3 && axis < 0; ++a) {
                if (coord(c, a) == box.lines[a].front()) axis = a;
                if (coord(c, a) == box.lines[a].back()) axis = a, high = true;
            }
            if (axis < 0) throw std::runtime_error("ring end is not on a box face");
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            holes[axis][high].push_back({static_cast<int>(line_index(box.lines[u], coord(c, u))),
                                         static_cast<int>(line_index(box.lines[v], coord(c, v))), rn.outer[s]});
        }
    }
    for (int a = 0; a < 3; ++a)
        for (int high = 0; high < 2; ++high) add_face(b, box, a, high == 1, holes[a][high]);
    b.scene.box_volume = box.lines[0].back() * box.lines[1].back() * box.lines[2].back();
    return std::move(b.scene);
}

}  // namespace tubemesh::testing
