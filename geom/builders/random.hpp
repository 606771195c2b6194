#pragma once
// The builders' random numbers: the same seed gives the same blocks with any standard library
// (std::uniform_real_distribution may differ between them; this does not).
#include <cstdint>
#include <random>

namespace tubemesh::geom {

class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    int integer(int lo, int hi) { return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1)); }

private:
    std::mt19937_64 engine_;
};

}  // namespace tubemesh::geom
