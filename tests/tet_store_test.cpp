// The tet store's arrays: contents kept while a block grows from malloc's to a mapping of its
// own, grows and shrinks as a mapping, moves, and is copied by name.
#include <gtest/gtest.h>

#include <cstddef>
#include <initializer_list>
#include <utility>

#include "engine/delaunay/huge_pages.hpp"
#include "engine/delaunay/tet_store.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::delaunay;

index_t value_at(std::size_t i) { return static_cast<index_t>(i * 2654435761u); }

void fill(PodArray<index_t>& a, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) a[i] = value_at(i);
}

bool holds(const PodArray<index_t>& a, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (a[i] != value_at(i)) return false;
    return true;
}

TEST(PodArray, KeepsItsContentsAcrossMallocAndMappedSizes) {
    constexpr std::size_t kSmall = 1000;                                      // malloc's
    constexpr std::size_t kMapped = 2 * kMappedBlockBytes / sizeof(index_t);  // a mapping
    constexpr std::size_t kHuge = 3 * kHugeBlockBytes / sizeof(index_t);      // advised to huge pages
    PodArray<index_t> a;
    a.reallocate(kSmall);
    fill(a, 0, kSmall);
    a.reallocate(kMapped);  // malloc's block into a mapping
    EXPECT_EQ(a.capacity(), kMapped);
    EXPECT_TRUE(holds(a, kSmall));
    fill(a, kSmall, kMapped);
    a.reallocate(kHuge);  // the mapping grows
    EXPECT_TRUE(holds(a, kMapped));
    fill(a, kMapped, kHuge);
    a.reallocate(kHuge + 12345);  // by less than a page's worth of ids and more
    EXPECT_TRUE(holds(a, kHuge));
    a.reallocate(kSmall + 1);  // shrinks, still a mapping
    EXPECT_EQ(a.capacity(), kSmall + 1);
    EXPECT_TRUE(holds(a, kSmall + 1));
    a.reallocate(kMapped);
    EXPECT_TRUE(holds(a, kSmall + 1));
    a.reallocate(0);
    EXPECT_EQ(a.capacity(), 0u);
    EXPECT_EQ(a.data(), nullptr);
}

TEST(PodArray, MovesMappedAndMallocBlocks) {
    constexpr std::size_t kMapped = kMappedBlockBytes / sizeof(index_t) + 7;
    PodArray<index_t> mapped, small;
    mapped.reallocate(kMapped);
    fill(mapped, 0, kMapped);
    small.reallocate(10);
    fill(small, 0, 10);
    PodArray<index_t> moved(std::move(mapped));
    EXPECT_EQ(mapped.capacity(), 0u);
    EXPECT_TRUE(holds(moved, kMapped));
    moved = std::move(small);  // the mapping is released, the malloc block taken over
    EXPECT_EQ(moved.capacity(), 10u);
    EXPECT_TRUE(holds(moved, 10));
    small = std::move(moved);
    EXPECT_TRUE(holds(small, 10));
}

TEST(TetStore, ReserveCloneAndShrinkKeepTheSlots) {
    TetStore store;
    const index_t n = static_cast<index_t>(kHugeBlockBytes / (4 * sizeof(index_t)) + 100);  // mapped arrays
    for (const index_t grow : {index_t{16}, index_t{1000}, index_t{100000}, n}) {
        const index_t before = store.size();
        store.reserve(grow);
        store.set_size(grow);
        for (index_t t = before; t < grow; ++t)
            for (index_t k = 0; k < 4; ++k) {
                store.vertex(t)[k] = 4 * t + k;
                store.neighbour(4 * t + k) = value_at(4 * t + k);
            }
    }
    ASSERT_EQ(store.size(), n);
    store.reserve(2 * std::size_t{n});
    store.shrink_to_fit();
    EXPECT_EQ(store.capacity(), n);
    const TetStore copy = store.clone();
    for (const TetStore* s : {static_cast<const TetStore*>(&store), &copy})
        for (index_t t = 0; t < n; ++t)
            for (index_t k = 0; k < 4; ++k) {
                ASSERT_EQ(s->vertex(t)[k], 4 * t + k);
                ASSERT_EQ(s->neighbour(4 * t + k), value_at(4 * t + k));
            }
}

}  // namespace
