#pragma once
// Filtering in parallel with the serial loop's result: fixed chunks count what they keep, the
// counts' prefix sums give every chunk its first output place, and the chunks then write their
// items in order. The output does not depend on the thread count or on timing.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <tbb/parallel_for.h>

#include "engine/core/types.hpp"

namespace tubemesh {

// Calls emit(i, k) for every i in [0, n) with keep(i), where k counts those i from 0 in
// increasing order, and returns how many; sized(count) runs once before the first emit (to size
// the output). keep(i) is asked twice (once to count, once to emit) and must give the same
// answer both times; emit writes only its own output place k.
template <class Keep, class Sized, class Emit>
std::size_t ordered_compact(std::size_t n, Keep&& keep, Sized&& sized, Emit&& emit) {
    constexpr std::size_t kChunk = 8192;
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    const auto begin = [&](std::size_t c) { return std::min(n, c * kChunk); };
    std::vector<std::size_t> first(chunks + 1, 0);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        std::size_t kept = 0;
        for (std::size_t i = begin(c); i < begin(c + 1); ++i) kept += keep(i) ? 1 : 0;
        first[c + 1] = kept;
    });
    for (std::size_t c = 0; c < chunks; ++c) first[c + 1] += first[c];
    sized(first[chunks]);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        std::size_t k = first[c];
        for (std::size_t i = begin(c); i < begin(c + 1); ++i)
            if (keep(i)) emit(i, k++);
    });
    return first[chunks];
}

// The i in [0, n) with keep(i), increasing (as the serial loop would list them).
template <class Keep>
std::vector<index_t> kept_indices(std::size_t n, Keep&& keep) {
    std::vector<index_t> out;
    ordered_compact(
        n, keep, [&](std::size_t count) { out.resize(count); },
        [&](std::size_t i, std::size_t k) { out[k] = static_cast<index_t>(i); });
    return out;
}

// out[k] = in[i] for the i with keep(i), in order.
template <class T, class Alloc, class Keep>
std::vector<T> kept_items(const std::vector<T, Alloc>& in, Keep&& keep) {
    std::vector<T> out;
    ordered_compact(
        in.size(), keep, [&](std::size_t count) { out.resize(count); },
        [&](std::size_t i, std::size_t k) { out[k] = in[i]; });
    return out;
}

}  // namespace tubemesh
