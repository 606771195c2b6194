#include "tests/support/tet_domain_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "engine/delaunay/tet_store.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/tets/recovery/boundary_recovery.hpp"

namespace tubemesh::testing {
namespace {

std::array<index_t, 3> sorted(index_t a, index_t b, index_t c) {
    std::array<index_t, 3> t{a, b, c};
    std::sort(t.begin(), t.end());
    return t;
}

}  // namespace

void box_front(const double lo[3], const double hi[3], int n, bool outward, std::vector<double>& xyz,
               std::vector<index_t>& front) {
    std::map<std::array<long, 3>, index_t> ids;
    const auto id = [&](const double p[3]) {
        const std::array<long, 3> key{std::lround(p[0] * 1e6), std::lround(p[1] * 1e6), std::lround(p[2] * 1e6)};
        const auto [it, fresh] = ids.emplace(key, static_cast<index_t>(xyz.size() / 3));
        if (fresh) xyz.insert(xyz.end(), p, p + 3);
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // (a, b, axis) right-handed
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    index_t q[4];
                    const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                    for (int k = 0; k < 4; ++k) {
                        double p[3];
                        p[axis] = side ? hi[axis] : lo[axis];
                        p[a] = lo[a] + (hi[a] - lo[a]) * (i + di[k]) / n;
                        p[b] = lo[b] + (hi[b] - lo[b]) * (j + dj[k]) / n;
                        q[k] = id(p);
                    }
                    // Counter-clockwise in (a, b) points along +axis: outward on the high side.
                    const bool flip = (side == 0) == outward;
                    const index_t t[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
                    for (int k = 0; k < 6; k += 3) {
                        front.push_back(t[k]);
                        front.push_back(flip ? t[k + 2] : t[k + 1]);
                        front.push_back(flip ? t[k + 1] : t[k + 2]);
                    }
                }
        }
}

void cube_front(double lo, double hi, int n, bool outward, std::vector<double>& xyz, std::vector<index_t>& front) {
    const double l[3] = {lo, lo, lo}, h[3] = {hi, hi, hi};
    box_front(l, h, n, outward, xyz, front);
}

tets::TetDomain recovered_cube_with_hole(int hole_cells) {
    std::vector<double> xyz;
    std::vector<index_t> front;
    cube_front(0.0, 1.0, 10, true, xyz, front);
    cube_front(0.35, 0.65, hole_cells, false, xyz, front);
    return tets::recover_boundary(xyz, front, Parallelism{2, 2});
}

void expect_valid(const tets::TetDomain& d, const std::vector<index_t>& front) {
    std::set<std::array<index_t, 3>> boundary;
    for (index_t t = 0; t < d.tets.size(); ++t) {
        const index_t* v = d.tets.vertex(t);
        for (int i = 0; i < 4; ++i) ASSERT_LT(v[i], d.point_count());
        ASSERT_GT(predicates::orient3d(d.point(v[0]), d.point(v[1]), d.point(v[2]), d.point(v[3])), 0) << "tet " << t;
        for (unsigned f = 0; f < 4; ++f) {
            const auto& node = tubemesh::kTetTopology.face[f].node;
            const index_t code = d.tets.neighbour(4 * t + f);
            if (code == delaunay::kNoAdjacent) {
                boundary.insert(sorted(v[node[0]], v[node[1]], v[node[2]]));
                continue;
            }
            ASSERT_EQ(d.tets.neighbour(code), 4 * t + f);
            const index_t* w = d.tets.vertex(code >> 2);
            const auto& node2 = tubemesh::kTetTopology.face[code & 3].node;
            ASSERT_EQ(sorted(v[node[0]], v[node[1]], v[node[2]]), sorted(w[node2[0]], w[node2[1]], w[node2[2]]));
        }
    }
    std::set<std::array<index_t, 3>> want;
    for (std::size_t i = 0; i < front.size(); i += 3) want.insert(sorted(front[i], front[i + 1], front[i + 2]));
    EXPECT_EQ(boundary, want) << "the boundary is not exactly the front";
    std::vector<std::uint8_t> used(d.point_count(), 0);
    for (index_t v : d.tets.vertices()) used[v] = 1;
    for (index_t v = d.front_points; v < d.point_count(); ++v) EXPECT_TRUE(used[v]) << "point " << v << " in no tet";
}

}  // namespace tubemesh::testing
