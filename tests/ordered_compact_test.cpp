// ordered_compact, kept_indices and kept_items against the serial filter loop, on sizes around
// the chunk boundary, at 1 and 2 threads; UninitVector keeps what it held when it grows.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "engine/core/ordered_compact.hpp"
#include "engine/core/uninit_vector.hpp"

namespace {

using namespace tubemesh;

TEST(OrderedCompact, MatchesTheSerialFilterAtAnyThreadCount) {
    std::mt19937_64 rng(7);
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{8191}, std::size_t{8192}, std::size_t{8193},
                          std::size_t{100003}}) {
        std::vector<double> value(n);
        std::vector<std::uint8_t> keep(n);
        for (std::size_t i = 0; i < n; ++i) {
            value[i] = std::uniform_real_distribution<double>(-1, 1)(rng);
            keep[i] = rng() % 3 == 0;  // runs of kept and dropped items of every length
        }
        std::vector<index_t> expected_index;
        std::vector<double> expected_value;
        for (std::size_t i = 0; i < n; ++i)
            if (keep[i]) {
                expected_index.push_back(static_cast<index_t>(i));
                expected_value.push_back(value[i]);
            }
        for (int threads : {1, 2}) {
            tbb::task_arena arena(threads);
            arena.execute([&] {
                const auto kept = [&](std::size_t i) { return keep[i] != 0; };
                EXPECT_EQ(kept_indices(n, kept), expected_index) << n << " items, " << threads << " threads";
                EXPECT_EQ(kept_items(value, kept), expected_value) << n << " items, " << threads << " threads";
                std::size_t sized = 0;
                std::vector<std::size_t> place(n, n);
                const std::size_t count = ordered_compact(
                    n, kept, [&](std::size_t c) { sized = c; }, [&](std::size_t i, std::size_t k) { place[i] = k; });
                EXPECT_EQ(count, expected_index.size());
                EXPECT_EQ(sized, count);
                for (std::size_t k = 0; k < expected_index.size(); ++k) EXPECT_EQ(place[expected_index[k]], k);
            });
        }
    }
}

TEST(OrderedCompact, UninitVectorKeepsItsElementsWhenItGrows) {
    UninitVector<index_t> v{3, 1, 4};
    v.resize(100000);
    v.resize(200000);
    EXPECT_EQ(v[0], 3u);
    EXPECT_EQ(v[1], 1u);
    EXPECT_EQ(v[2], 4u);
    v.push_back(5);
    EXPECT_EQ(v.back(), 5u);
    EXPECT_EQ(v.size(), 200001u);
}

}  // namespace
