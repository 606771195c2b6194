#include "engine/tets/domain/point_colouring.hpp"

#include <algorithm>
#include <cstddef>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace tubemesh::tets {

namespace {

// Fixed chunk sizes for the colouring: its work is split the same way whatever the thread
// count, so every chunk's part of the result, and the order the parts are combined in, is fixed.
constexpr std::size_t kRowsPerChunk = std::size_t{1} << 18;
constexpr std::size_t kMaxChunks = 8;
constexpr std::size_t kPointsPerChunk = 2048;
constexpr std::size_t kPointsPerBlock = 4096;

}  // namespace

Incidence build_incidence(const TetDomain& dom) {
    Incidence inc;
    const std::size_t points = dom.point_count();
    const std::span<const index_t> v = dom.tets.vertices();
    const std::size_t rows = v.size();
    // No more chunks than threads: every chunk costs a pass over all points, and any split
    // gives the same result (each point's tets in increasing order).
    const std::size_t threads = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    const std::size_t chunks = std::clamp<std::size_t>(rows / kRowsPerChunk, 1, std::min(kMaxChunks, threads));
    const auto chunk_begin = [&](std::size_t c) { return rows * c / chunks; };
    // count[c][p]: entries of point p in chunk c; then where chunk c's first one goes.
    std::vector<std::vector<index_t>> count(chunks);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        count[c].assign(points, 0);
        for (std::size_t k = chunk_begin(c); k < chunk_begin(c + 1); ++k) ++count[c][v[k]];
    });
    // Integer prefix sums over fixed blocks of points: exact, so the same for any thread count.
    inc.offsets.resize(points + 1);
    inc.offsets[0] = 0;
    const std::size_t blocks = (points + kPointsPerBlock - 1) / kPointsPerBlock;
    std::vector<index_t> block_first(blocks + 1, 0);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        index_t at = 0;
        for (std::size_t p = b * kPointsPerBlock; p < std::min(points, (b + 1) * kPointsPerBlock); ++p) {
            for (std::size_t c = 0; c < chunks; ++c) at += count[c][p];
            inc.offsets[p + 1] = at;
        }
        block_first[b + 1] = at;
    });
    for (std::size_t b = 0; b < blocks; ++b) block_first[b + 1] += block_first[b];
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        for (std::size_t p = b * kPointsPerBlock; p < std::min(points, (b + 1) * kPointsPerBlock); ++p)
            inc.offsets[p + 1] += block_first[b];
    });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t p = r.begin(); p != r.end(); ++p) {
            index_t at = inc.offsets[p];
            for (std::size_t c = 0; c < chunks; ++c) {
                const index_t n = count[c][p];
                count[c][p] = at;
                at += n;
            }
        }
    });
    inc.tets.resize(rows);
    // Chunks in row order and rows in order inside each: every point's tets come out increasing.
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        std::vector<index_t>& at = count[c];
        for (std::size_t k = chunk_begin(c); k < chunk_begin(c + 1); ++k)
            inc.tets[at[v[k]]++] = static_cast<index_t>(k / 4);
    });
    return inc;
}

std::vector<std::vector<index_t>> colour_points(const TetDomain& dom, const Incidence& inc,
                                                std::span<const index_t> points,
                                                std::vector<std::uint32_t>& colour) {
    // A point's colour depends only on the colours of its neighbours before it in `points`.
    // Listing those neighbours (once each) reads every tet of every star: that part runs in
    // parallel, over fixed chunks of `points`, and leaves the serial greedy pass a few reads
    // per point instead of four per incident tet.
    constexpr std::uint32_t kListed = kNoIndex - 1;  // in `points`, not coloured yet
    for (index_t p : points) colour[p] = kListed;
    const std::size_t chunks = (points.size() + kPointsPerChunk - 1) / kPointsPerChunk;
    struct Earlier {
        std::vector<index_t> offsets, points;
    };
    std::vector<Earlier> earlier(chunks);
    // listed_for[q] == p: q is on p's list already (one array per thread).
    tbb::enumerable_thread_specific<std::vector<index_t>> listed_for(
        [&] { return std::vector<index_t>(colour.size(), kNoIndex); });
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        Earlier& e = earlier[c];
        std::vector<index_t>& listed = listed_for.local();
        const std::size_t end = std::min(points.size(), (c + 1) * kPointsPerChunk);
        e.offsets.reserve(end - c * kPointsPerChunk + 1);
        e.offsets.push_back(0);
        for (std::size_t i = c * kPointsPerChunk; i < end; ++i) {
            const index_t p = points[i];
            for (index_t t : inc.of(p))
                for (int k = 0; k < 4; ++k) {
                    const index_t q = dom.tets.vertex(t)[k];
                    if (q < p && listed[q] != p && colour[q] != kNoIndex) {
                        listed[q] = p;
                        e.points.push_back(q);
                    }
                }
            e.offsets.push_back(static_cast<index_t>(e.points.size()));
        }
    });
    std::vector<index_t> seen;  // seen[c] == p: colour c is taken by a neighbour of p
    std::vector<std::vector<index_t>> classes;
    for (std::size_t c = 0; c < chunks; ++c) {
        const Earlier& e = earlier[c];
        for (std::size_t j = 0; j + 1 < e.offsets.size(); ++j) {
            const index_t p = points[c * kPointsPerChunk + j];
            for (index_t k = e.offsets[j]; k < e.offsets[j + 1]; ++k) seen[colour[e.points[k]]] = p;
            std::uint32_t col = 0;
            while (col < seen.size() && seen[col] == p) ++col;
            if (col == seen.size()) {
                seen.push_back(kNoIndex);
                classes.emplace_back();
            }
            colour[p] = col;
            classes[col].push_back(p);
        }
    }
    for (index_t p : points) colour[p] = kNoIndex;
    return classes;
}

}  // namespace tubemesh::tets
