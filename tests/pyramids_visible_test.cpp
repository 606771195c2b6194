// What one front looks at (engine/pyramids/visible.hpp) when the surface ahead is meshed far finer
// than its quad, as a tet hole's wall in a narrow gap is: the existing nodes it judges are the
// nearest few, over a thin ring only those within the paper's radius scaled to the room ahead, and
// the faces of a node are listed exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "engine/pyramids/face_tree.hpp"
#include "engine/pyramids/front_state.hpp"
#include "engine/pyramids/fronts.hpp"
#include "engine/pyramids/visible.hpp"
#include "tests/support/ring_scene.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::pyramids;
namespace scene = tubemesh::testing;

// A ring of outer radius 1 along z whose lowest node column runs 0.3 above the face y = 0, under
// grid lines every 0.02 along z: every box face along the ring holds thousands of nodes within
// the paper's candidate radius of a quad facing the floor.
scene::RingScene fine_floor_scene() {
    const double a = 2.0 * std::sin(std::numbers::pi / 8);
    const double length = 4 * 1.5 * a;
    scene::BoxGrid box;
    box.lines[0] = {0, 1, 3 - 1.7, 3, 3 + 1.7, 5, 6};
    box.lines[1] = {0, 1.3, 1.3 + 1.7, 5};
    box.lines[2] = scene::spaced(0, length, static_cast<int>(std::ceil(length / 0.02)));
    return scene::build_ring_scene(box, {scene::straight_ring(3, 1.3, 0, length, 4, 1.0, 0.5)});
}

struct Gathered {
    scene::RingScene s = fine_floor_scene();
    std::vector<Front> fronts;
    Adjacency neighbours;
    std::vector<Box> boxes;

    explicit Gathered(double room) {
        std::vector<double> scale(s.front_quads.size() / 4, room);
        fronts = make_fronts(s.mesh, s.front_quads, s.boundary_triangles, PyramidOptions{}, nullptr,
                             room < 1 ? std::span<const double>(scale) : std::span<const double>());
        neighbours = front_neighbours(fronts);
        for (std::size_t i = 0; i < s.boundary_triangles.size(); i += 3) {
            Box b = Box::of(s.mesh.point(s.boundary_triangles[i]));
            for (int k = 1; k < 3; ++k) b.add(s.mesh.point(s.boundary_triangles[i + k]));
            boxes.push_back(b);
        }
        for (std::size_t i = 0; i < s.obstacle_quads.size(); i += 4) {
            Box b = Box::of(s.mesh.point(s.obstacle_quads[i]));
            for (int k = 1; k < 4; ++k) b.add(s.mesh.point(s.obstacle_quads[i + k]));
            boxes.push_back(b);
        }
    }

    // The front whose normal points most nearly down at the floor.
    index_t facing_the_floor() const {
        index_t best = 0;
        for (index_t i = 0; i < fronts.size(); ++i)
            if (fronts[i].normal.y < fronts[best].normal.y) best = i;
        return best;
    }

    // The nodes on the front (boundary triangles' and quads' corners) but f's own corners within
    // the candidate radius of N, nearest first (ties by id): what the paper calls candidates.
    std::vector<std::pair<double, index_t>> all_candidates(const Front& f) const {
        std::set<index_t> nodes(s.boundary_triangles.begin(), s.boundary_triangles.end());
        nodes.insert(s.front_quads.begin(), s.front_quads.end());
        std::vector<std::pair<double, index_t>> out;
        for (index_t n : nodes) {
            if (std::find(f.node.begin(), f.node.end(), n) != f.node.end()) continue;
            const double d2 = distance2(s.mesh.point(n), f.ideal);
            if (d2 < f.candidate_radius * f.candidate_radius) out.emplace_back(d2, n);
        }
        std::sort(out.begin(), out.end());
        return out;
    }
};

TEST(PyramidVisible, AFrontOverAFineSurfaceJudgesOnlyItsNearestCandidates) {
    const Gathered g(1.0);
    const FaceTree tree(g.boxes);
    const FrontState state(g.s.mesh, g.fronts, g.s.boundary_triangles);
    const World world{g.fronts, g.neighbours, tree, static_cast<index_t>(g.s.boundary_triangles.size() / 3),
                      g.s.obstacle_quads, state};
    const index_t i = g.facing_the_floor();
    Visible vis;
    gather_visible(world, i, vis);

    const auto all = g.all_candidates(g.fronts[i]);
    ASSERT_GT(all.size(), 200u) << "the scene must put many nodes in reach";
    EXPECT_LE(vis.candidates.size(), 32u);
    ASSERT_FALSE(vis.candidates.empty());
    for (std::size_t k = 0; k < vis.candidates.size(); ++k) EXPECT_EQ(vis.candidates[k].id, all[k].second) << k;
}

TEST(PyramidVisible, OverAThinRingTheCandidatesAreWithinTheRoomAhead) {
    const double room = 0.1;  // the apex's share of the paper's height, as thin_rings.hpp gives it
    const Gathered g(room);
    const FaceTree tree(g.boxes);
    const FrontState state(g.s.mesh, g.fronts, g.s.boundary_triangles);
    const World world{g.fronts, g.neighbours, tree, static_cast<index_t>(g.s.boundary_triangles.size() / 3),
                      g.s.obstacle_quads, state};
    const index_t i = g.facing_the_floor();
    const Front& f = g.fronts[i];
    ASSERT_TRUE(f.lowered);
    ASSERT_LT(f.spacing, 0.2 * f.h);
    Visible vis;
    gather_visible(world, i, vis);
    const double radius = PyramidOptions{}.search_radius_factor * f.spacing;
    for (const NearNode& n : vis.candidates) EXPECT_LT(std::sqrt(n.d2), radius * (1 + 1e-12));
    // And the faces it looks at reach no farther than its pyramids plus the largest distance
    // threshold, which is the spacing's share too.
    const double query = f.reach + PyramidOptions{}.distance_factor * f.spacing;
    for (const VisibleFace& face : vis.faces) EXPECT_LT(std::sqrt(box_distance2(face.box, f.ideal)), query * (1 + 1e-9));
}

TEST(PyramidVisible, TheFacesOfANodeAreThoseThatHoldIt) {
    const Gathered g(1.0);
    const FaceTree tree(g.boxes);
    const FrontState state(g.s.mesh, g.fronts, g.s.boundary_triangles);
    const World world{g.fronts, g.neighbours, tree, static_cast<index_t>(g.s.boundary_triangles.size() / 3),
                      g.s.obstacle_quads, state};
    Visible vis;
    // Two gathers, so the second's lists must not see the first's.
    for (const index_t i : {g.facing_the_floor(), index_t{0}}) {
        gather_visible(world, i, vis);
        std::set<index_t> nodes;
        for (const VisibleFace& face : vis.faces)
            for (int k = 0; k < face.size; ++k) nodes.insert(face.node[k]);
        nodes.insert(0);  // a node that may be in no face
        for (index_t n : nodes) {
            std::vector<const VisibleFace*> want, got;
            for (const VisibleFace& face : vis.faces)
                if (face.has(n)) want.push_back(&face);
            vis.for_each_face_of(n, [&](const VisibleFace& face) { got.push_back(&face); });
            ASSERT_EQ(got, want) << "node " << n;
        }
    }
}

}  // namespace
