#pragma once
// The unit of parallel work: a run of consecutive stations of one tube. Fixed by the input
// alone (never by the thread count), so everything that depends on how stations are grouped —
// the wall projections' hints — comes out the same for every thread count.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace tubemesh::sweep {

// Small enough that one long pipe keeps two cores busy, large enough that a task outweighs
// its scheduling (a station of 24 nodes takes about a microsecond).
inline constexpr int kStationsPerChunk = 32;

struct StationChunk {
    std::size_t tube;
    int first, last;  // stations [first, last)
};

// Chunks of every tube in tube order; `stations(t)` is tube t's station count.
template <class Stations>
std::vector<StationChunk> station_chunks(std::size_t tubes, Stations stations) {
    std::vector<StationChunk> chunks;
    for (std::size_t t = 0; t < tubes; ++t)
        for (int s = 0; s < stations(t); s += kStationsPerChunk)
            chunks.push_back({t, s, std::min(s + kStationsPerChunk, stations(t))});
    return chunks;
}

}  // namespace tubemesh::sweep
