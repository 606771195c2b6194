#include "engine/delaunay/insertion_order.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <memory>
#include <utility>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "engine/delaunay/huge_pages.hpp"

namespace tubemesh::delaunay {
namespace {

constexpr int kGridBits = 16;           // 65536 cells per axis: ample for 1e9 points
constexpr index_t kSmallestRound = 512;  // the first round holds at least about this many points

std::uint64_t spread_bits(std::uint64_t v) {  // 21 bits -> every third bit of 63
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

struct Keyed {
    std::uint64_t key;
    index_t id;
};

// Stable LSD radix sort on the top `bits` of the 48-bit keys, 8 bits per pass. Chunks count
// and scatter in parallel; chunk order keeps it stable, so equal keys keep id order and the
// result does not depend on the thread count.
void radix_sort(std::span<Keyed> a, std::span<Keyed> tmp, int bits) {
    const std::size_t n = a.size();
    if (n < 2) return;
    const std::size_t chunks = std::clamp<std::size_t>(n / 32768, 1, 64);
    const auto chunk_begin = [&](std::size_t c) { return n * c / chunks; };
    std::vector<std::array<std::size_t, 256>> count(chunks);
    Keyed* src = a.data();
    Keyed* dst = tmp.data();
    for (int shift = 3 * kGridBits - bits; shift < 3 * kGridBits; shift += 8) {
        const auto digit = [shift](const Keyed& k) { return static_cast<std::size_t>((k.key >> shift) & 0xff); };
        tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
            count[c].fill(0);
            for (std::size_t i = chunk_begin(c); i < chunk_begin(c + 1); ++i) ++count[c][digit(src[i])];
        });
        std::size_t first_digit_total = 0;
        for (std::size_t c = 0; c < chunks; ++c) first_digit_total += count[c][digit(src[0])];
        if (first_digit_total == n) continue;  // all in one bucket
        std::size_t sum = 0;
        for (std::size_t d = 0; d < 256; ++d)
            for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(count[c][d], sum);
        tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
            for (std::size_t i = chunk_begin(c); i < chunk_begin(c + 1); ++i) dst[count[c][digit(src[i])]++] = src[i];
        });
        std::swap(src, dst);
    }
    if (src != a.data()) std::copy(src, src + n, a.data());
}

}  // namespace

// Skilling, "Programming the Hilbert curve" (AIP Conf. Proc. 707, 2004): axes to transposed
// Hilbert index, then the transposed bits interleaved into one integer.
std::uint64_t hilbert_key(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz, int bits) {
    std::uint32_t X[3] = {ix, iy, iz};
    const std::uint32_t m = 1u << (bits - 1);
    // Branch-free form of "if bit q of X[i]: invert the low bits of X[0], else exchange the
    // low bits of X[0] and X[i]" (random points make those branches unpredictable).
    for (std::uint32_t q = m; q > 1; q >>= 1) {
        const std::uint32_t p = q - 1;
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t set = 0u - ((X[i] & q) != 0);
            const std::uint32_t t = (X[0] ^ X[i]) & p & ~set;
            X[0] ^= (p & set) | t;
            X[i] ^= t;
        }
    }
    X[1] ^= X[0];
    X[2] ^= X[1];
    std::uint32_t t = 0;
    for (std::uint32_t q = m; q > 1; q >>= 1) t ^= (q - 1) & (0u - ((X[2] & q) != 0));
    for (auto& c : X) c ^= t;
    return spread_bits(X[0]) << 2 | spread_bits(X[1]) << 1 | spread_bits(X[2]);
}

std::uint64_t InsertionOrder::key_of(double x, double y, double z) const {
    const double cells = double(1u << kGridBits);
    const auto cell = [&](double v, int a) {
        const double c = std::floor((v - grid_lo[a]) * grid_scale);
        return static_cast<std::uint32_t>(std::clamp(c, 0.0, cells - 1));
    };
    return hilbert_key(cell(x, 0), cell(y, 1), cell(z, 2), kGridBits);
}

InsertionOrder brio_hilbert_order(std::span<const double> x, std::span<const double> y,
                                  std::span<const double> z) {
    const std::size_t n = x.size();
    InsertionOrder out;
    if (n == 0) {
        out.round_begin = {0};
        return out;
    }
    // Every pass over the points runs on fixed chunks, so the counts and the stable scatter
    // below do not depend on the thread count, and the pages of the fresh arrays are first
    // touched by both threads instead of one.
    const std::size_t chunks = std::clamp<std::size_t>(n / 32768, 1, 64);
    const auto chunk_begin = [&](std::size_t c) { return n * c / chunks; };

    // Round of each point: P(round from the end >= k) = 8^-k, capped so the first is not tiny.
    int last = 0;
    for (std::size_t s = n; s >= 8 * std::size_t{kSmallestRound}; s /= 8) ++last;
    const auto rounds = static_cast<std::size_t>(last) + 1;
    const auto round_of = [last](std::size_t i) {
        return last - std::min(std::countl_zero(splitmix64(i) | 1) / 3, last);
    };
    // count[c * rounds + r]: points of chunk c in round r; then, after the prefix sums in
    // (round, chunk) order, where chunk c's first point of round r goes.
    std::vector<std::size_t> count(chunks * rounds, 0);
    struct Box {
        double lo[3], hi[3];
    };
    std::vector<Box> box(chunks);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        Box b{{x[chunk_begin(c)], y[chunk_begin(c)], z[chunk_begin(c)]}, {x[chunk_begin(c)], y[chunk_begin(c)], z[chunk_begin(c)]}};
        for (std::size_t i = chunk_begin(c); i < chunk_begin(c + 1); ++i) {
            ++count[c * rounds + static_cast<std::size_t>(round_of(i))];
            const double p[3] = {x[i], y[i], z[i]};
            for (int a = 0; a < 3; ++a) {
                b.lo[a] = std::min(b.lo[a], p[a]);
                b.hi[a] = std::max(b.hi[a], p[a]);
            }
        }
        box[c] = b;
    });
    out.round_begin.assign(rounds + 1, 0);
    {
        std::size_t sum = 0;
        for (std::size_t r = 0; r < rounds; ++r) {
            out.round_begin[r] = static_cast<index_t>(sum);
            for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(count[c * rounds + r], sum);
        }
        out.round_begin[rounds] = static_cast<index_t>(sum);
    }

    // Quantise on a cube so the curve is not stretched along a long axis.
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = box[0].lo[a];
        hi[a] = box[0].hi[a];
        for (const Box& b : box) {
            lo[a] = std::min(lo[a], b.lo[a]);
            hi[a] = std::max(hi[a], b.hi[a]);
        }
    }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    for (int a = 0; a < 3; ++a) out.grid_lo[a] = lo[a];
    out.grid_scale = extent > 0 ? double(1u << kGridBits) / extent : 0.0;

    // Uninitialised (std::vector would zero 2 x 16 bytes per point on one thread first).
    const std::unique_ptr<Keyed[]> keyed_block(new Keyed[n]);
    const std::unique_ptr<Keyed[]> tmp_block(new Keyed[n]);
    advise_huge_pages(keyed_block.get(), n * sizeof(Keyed));
    advise_huge_pages(tmp_block.get(), n * sizeof(Keyed));
    const std::span<Keyed> keyed(keyed_block.get(), n), tmp(tmp_block.get(), n);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        std::size_t* at = count.data() + c * rounds;
        for (std::size_t i = chunk_begin(c); i < chunk_begin(c + 1); ++i) {
            Keyed& k = keyed[at[round_of(i)]++];
            k.id = static_cast<index_t>(i);
            k.key = out.key_of(x[i], y[i], z[i]);
        }
    });

    out.order.resize(n);
    out.key.resize(n);
    for (std::size_t r = 0; r < rounds; ++r) {
        const index_t b = out.round_begin[r], e = out.round_begin[r + 1];
        // A round of m points needs about log2(m) + 6 key bits to order its neighbourhoods.
        const int need = std::bit_width(std::uint64_t{e - b}) + 6;
        radix_sort(keyed.subspan(b, e - b), tmp, std::min(3 * kGridBits, (need + 7) / 8 * 8));
        const bool backwards = r % 2 == 1;
        tbb::parallel_for(tbb::blocked_range<index_t>(0, e - b, 16384), [&](const tbb::blocked_range<index_t>& k) {
            for (index_t i = k.begin(); i < k.end(); ++i) {
                const Keyed& from = keyed[backwards ? e - 1 - i : b + i];
                out.order[b + i] = from.id;
                out.key[b + i] = from.key;
            }
        });
    }
    return out;
}

std::vector<index_t> curve_order(std::span<const double> xyz) {
    const std::size_t n = xyz.size() / 3;
    std::vector<index_t> order(n);
    if (n == 0) return order;
    // Fixed chunks: min and max do not depend on how the points are grouped, the keys are the
    // points' own, and (key, index) pairs are distinct, so every sort gives the one order.
    constexpr std::size_t kChunk = 16384;
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<std::array<double, 6>> box(chunks);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        std::array<double, 6> b{xyz[3 * c * kChunk], xyz[3 * c * kChunk + 1], xyz[3 * c * kChunk + 2]};
        std::copy_n(b.begin(), 3, b.begin() + 3);
        for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
            for (int a = 0; a < 3; ++a) {
                b[a] = std::min(b[a], xyz[3 * i + a]);
                b[3 + a] = std::max(b[3 + a], xyz[3 * i + a]);
            }
        box[c] = b;
    });
    double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {lo[0], lo[1], lo[2]};
    for (const auto& b : box)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b[a]);
            hi[a] = std::max(hi[a], b[3 + a]);
        }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
    const double scale = double((1u << 16) - 1) / extent;
    std::vector<std::pair<std::uint64_t, index_t>> key(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
            std::uint32_t g[3];
            for (int a = 0; a < 3; ++a) g[a] = static_cast<std::uint32_t>((xyz[3 * i + a] - lo[a]) * scale);
            key[i] = {hilbert_key(g[0], g[1], g[2], 16), static_cast<index_t>(i)};
        }
    });
    tbb::parallel_sort(key.begin(), key.end());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) order[i] = key[i].second;
    });
    return order;
}

}  // namespace tubemesh::delaunay
