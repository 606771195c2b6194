// Parts of the pyramid layer on their own: exact segment/triangle contact with shared
// nodes (the coplanar cases a straight ring produces everywhere) and its double filter, and
// conflict-free batches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "engine/pyramids/batches.hpp"
#include "engine/pyramids/contacts.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/pyramids/fronts.hpp"
#include "tests/support/ring_scene.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::pyramids;
namespace scene = tubemesh::testing;

// Triangle 10-11-12 in the plane z = 0; a candidate pyramid with its apex off that plane.
struct PyramidContact : ::testing::Test {
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    const std::array<index_t, 3> ids{10, 11, 12};
    const std::array<const Vec3*, 3> tri{&a, &b, &c};
    NewPyramid y{{20, 21, 22, 23, kNoIndex}, {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}}}};

    bool contact(index_t ip, Vec3 p, index_t iq, Vec3 q) const { return improper_contact(ip, p, iq, q, ids, tri, y); }
};

TEST_F(PyramidContact, SharedNodeOffThePlaneIsAllowed) {
    EXPECT_FALSE(contact(10, a, kNoIndex, {0.2, 0.2, 1}));
    EXPECT_FALSE(contact(kNoIndex, {0.2, 0.2, -1}, 11, b));
}

TEST_F(PyramidContact, AnEdgeOfTheTriangleIsAllowed) { EXPECT_FALSE(contact(10, a, 11, b)); }

TEST_F(PyramidContact, CollinearContinuationOfAnEdgeIsAllowed) {
    // The next axial edge of a straight ring beyond a pyramid face's base edge.
    EXPECT_FALSE(contact(11, b, 30, {2, 0, 0}));
    EXPECT_FALSE(contact(10, a, 30, {-1, 0, 0}));
    EXPECT_FALSE(contact(10, a, 30, {-1, -1, 0}));  // coplanar, pointing away
}

TEST_F(PyramidContact, CoplanarOverlapBeyondTheSharedNodeIsRefused) {
    EXPECT_TRUE(contact(11, b, 30, {0.5, 0, 0}));    // back along the edge
    EXPECT_TRUE(contact(10, a, 30, {0.2, 0.2, 0}));  // into the interior
    EXPECT_TRUE(contact(10, a, 30, {2, 2, 0}));      // across the opposite edge
}

TEST_F(PyramidContact, UnsharedContactOfAnyKindIsRefused) {
    EXPECT_TRUE(contact(30, {0.2, 0.2, -1}, 31, {0.2, 0.2, 1}));  // crossing
    EXPECT_TRUE(contact(30, {0.5, 0, 0}, 31, {0.5, -1, 0}));      // touching an edge
    EXPECT_TRUE(contact(30, {0.2, 0.2, 0}, 31, {0.2, 0.2, 1}));   // ending on the face
    EXPECT_FALSE(contact(30, {2, 2, -1}, 31, {2, 2, 1}));
    EXPECT_FALSE(contact(30, {0.2, 0.2, 0.1}, 31, {0.2, 0.2, 1}));
}

// The double filter never claims "off the plane" where the exact orient3d says coplanar or
// the other sign matters: whenever it decides, orient3d is not 0. On points in general
// position it decides nearly always; on exactly coplanar points, points rounded onto the plane
// and lengths outside its range, never.
TEST(PyramidOffPlane, DecidesOnlyWhatTheExactPredicateSays) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const auto random_point = [&](double scale) { return Vec3{scale * u(rng), scale * u(rng), scale * u(rng)}; };
    int decided = 0;
    const int trials = 20000;
    for (int i = 0; i < trials; ++i) {
        const double scale = std::pow(10.0, static_cast<int>(rng() % 13) - 6);
        const Vec3 s = random_point(scale), b = random_point(scale), c = random_point(scale), x = random_point(scale);
        if (!surely_off_plane(s, b, c, x)) continue;
        ++decided;
        EXPECT_NE(predicates::orient3d(s, b, c, x), 0);
    }
    EXPECT_GT(decided, trials * 99 / 100);

    int exact_zero = 0;
    for (int i = 0; i < trials; ++i) {
        // x on the plane of s, b, c up to rounding (and exactly on it for the lattice case).
        const Vec3 s = random_point(1), b = random_point(1), c = random_point(1);
        const double l = u(rng), m = u(rng);
        const Vec3 x = i % 2 == 0 ? s + l * (b - s) + m * (c - s) : Vec3{l, m, 0};
        const Vec3 p = i % 2 == 0 ? s : Vec3{s.x, s.y, 0}, q = i % 2 == 0 ? b : Vec3{b.x, b.y, 0},
                   r = i % 2 == 0 ? c : Vec3{c.x, c.y, 0};
        exact_zero += predicates::orient3d(p, q, r, x) == 0;
        EXPECT_FALSE(surely_off_plane(p, q, r, x));
        // Slightly off the plane: decided or not, never against the exact sign's being 0.
        const Vec3 off = x + Vec3{0, 0, 1e-7};
        if (surely_off_plane(p, q, r, off)) {
            EXPECT_NE(predicates::orient3d(p, q, r, off), 0);
        }
    }
    EXPECT_GE(exact_zero, trials / 2);  // the points in z = 0 at least

    // Degenerate triangles (a repeated node, collinear nodes) and lengths out of range.
    const Vec3 o{0, 0, 0}, e{1, 0, 0}, up{0, 0, 1};
    EXPECT_FALSE(surely_off_plane(o, o, e, up));
    EXPECT_FALSE(surely_off_plane(o, e, Vec3{2, 0, 0}, up));
    EXPECT_FALSE(surely_off_plane(o, Vec3{1e-80, 0, 0}, Vec3{0, 1e-80, 0}, Vec3{0, 0, 1e-80}));
    EXPECT_FALSE(surely_off_plane(o, Vec3{1e80, 0, 0}, Vec3{0, 1e80, 0}, Vec3{0, 0, 1e80}));
    EXPECT_TRUE(surely_off_plane(o, e, Vec3{0, 1, 0}, up));
    EXPECT_TRUE(surely_off_plane(o, e, Vec3{0, 1, 0}, Vec3{0.3, 0.3, -1e-6}));
}

// The plane made once and asked from any node of its triangle (the criteria measure a segment
// from the node it shares): the same guarantee, here on nearly flat triangles and on points
// near the plane, where the margin matters.
TEST(PyramidOffPlane, APlaneAskedFromAnyNodeDecidesOnlyWhatTheExactPredicateSays) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int decided = 0, undecided = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a{u(rng), u(rng), 0}, b{u(rng), u(rng), 1e-12 * u(rng)};
        const Vec3 c = i % 3 == 0 ? a + 1e-6 * (b - a) + Vec3{1e-9 * u(rng), 0, 0}  // a needle
                                  : Vec3{u(rng), u(rng), 1e-3 * u(rng)};
        const Vec3 x{u(rng), u(rng), std::pow(10.0, -static_cast<int>(rng() % 16)) * u(rng)};
        const PlaneFilter plane(a, b, c);
        for (const Vec3& s : {a, b, c}) {
            if (!plane.surely_off(s, x)) {
                ++undecided;
                continue;
            }
            ++decided;
            EXPECT_NE(predicates::orient3d(a, b, c, x), 0);
        }
    }
    EXPECT_GT(decided, 0);
    EXPECT_GT(undecided, 0);  // the points nearest the plane are left to the exact predicate
}

TEST(PyramidBatches, NoTwoNeighboursShareABatchAndEveryFrontHasOne) {
    const double a = 2.0 * std::sin(std::numbers::pi / 8);
    scene::BoxGrid box;
    box.lines[0] = {0, 1, 3, 5, 6};
    box.lines[1] = box.lines[0];
    box.lines[2] = scene::spaced(0, 40 * 1.5 * a, 20);
    const scene::RingScene s =
        scene::build_ring_scene(box, {scene::straight_ring(3, 3, 0, 40 * 1.5 * a, 40, 1.0, 0.5)});
    const std::vector<Front> fronts = make_fronts(s.mesh, s.front_quads, s.boundary_triangles, PyramidOptions{});
    const Adjacency nbr = front_neighbours(fronts);
    for (index_t i = 0; i < fronts.size(); ++i)
        for (index_t j : nbr.row(i)) {
            const auto back = nbr.row(j);
            EXPECT_TRUE(std::binary_search(back.begin(), back.end(), i)) << "neighbours are symmetric";
        }
    // Every front twice, in reverse order, and once more in a different order.
    std::vector<index_t> order(fronts.size());
    for (index_t i = 0; i < order.size(); ++i) order[i] = static_cast<index_t>(order.size() - 1 - i);
    Batcher batcher(static_cast<index_t>(fronts.size()));
    for (int round = 0; round < 2; ++round) {
        Adjacency batches;
        batcher.colour(order, nbr, batches);
        std::vector<int> batch_of(fronts.size(), -1);
        for (index_t b = 0; b + 1 < batches.offset.size(); ++b)
            for (index_t i : batches.row(b)) {
                EXPECT_EQ(batch_of[i], -1);
                batch_of[i] = static_cast<int>(b);
            }
        for (index_t i : order) {
            ASSERT_GE(batch_of[i], 0);
            for (index_t j : nbr.row(i)) EXPECT_NE(batch_of[i], batch_of[j]);
        }
        // The first front in the order is in the first batch.
        EXPECT_EQ(batch_of[order.front()], 0);
        std::rotate(order.begin(), order.begin() + 7, order.end());
    }
}

}  // namespace
