#include "engine/delaunay/delaunay.hpp"

#include <algorithm>
#include <numeric>
#include <cmath>
#include <string>

#include "engine/core/timing.hpp"
#include "engine/delaunay/insertion_order.hpp"
#include "engine/delaunay/triangulation.hpp"

namespace tubemesh::delaunay {
namespace {

// Tets per point of a uniform random set is about 6.75; ghosts and free slots add a little.
constexpr double kTetsPerPoint = 7.1;

}  // namespace

DelaunayResult delaunay(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                        const Parallelism& par, const DelaunayOptions& options) {
    const auto t_start = Clock::now();
    if (x.size() != y.size() || x.size() != z.size())
        throw Error("Delaunay: x, y and z hold " + std::to_string(x.size()) + ", " + std::to_string(y.size()) +
                    " and " + std::to_string(z.size()) + " coordinates; they must be equal");
    const std::size_t n = x.size();
    if (n + 8 >= kInfiniteVertex) throw Error("Delaunay: too many points for 32-bit ids");
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i]))
            throw Error("Delaunay: point " + std::to_string(i) + " has a NaN or infinite coordinate");

    if (par.parts == 0) throw Error("Delaunay: the part count must be at least 1");
    const unsigned parts = par.parts;
    DelaunayResult result;
    result.stats.points = static_cast<index_t>(n);
    result.stats.threads = par.threads;
    result.stats.partitions = parts;

    {
        InsertionOrder order = brio_hilbert_order(x, y, z);
        Triangulation tri;
        tri.set_pulse(options.pulse);
        tri.reserve_points(n + 8);

        // Kernel ids: box corners first, then the points in insertion order.
        if (options.bounding_box && n > 0) {
            double lo[3] = {x[0], y[0], z[0]}, hi[3] = {x[0], y[0], z[0]};
            for (std::size_t i = 0; i < n; ++i) {
                const double p[3] = {x[i], y[i], z[i]};
                for (int a = 0; a < 3; ++a) {
                    lo[a] = std::min(lo[a], p[a]);
                    hi[a] = std::max(hi[a], p[a]);
                }
            }
            double diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
            if (diag == 0) diag = 1;
            const double grow = options.box_margin * diag;
            double xyz[24];
            index_t ids[8];
            for (int k = 0; k < 8; ++k) {
                result.box_corners.push_back({(k & 1) ? hi[0] + grow : lo[0] - grow, (k & 2) ? hi[1] + grow : lo[1] - grow,
                                              (k & 4) ? hi[2] + grow : lo[2] - grow});
                std::copy(result.box_corners.back().begin(), result.box_corners.back().end(), xyz + 3 * k);
                ids[k] = static_cast<index_t>(n + k);
            }
            tri.add_points(xyz, ids);
        }
        tri.add_points(x, y, z, order.order);
        std::vector<index_t>().swap(order.order);  // the rounds are kernel id ranges now
        {
            std::vector<std::uint64_t> keys = std::move(order.key);
            if (!result.box_corners.empty()) {
                std::vector<std::uint64_t> corner_keys;
                for (const auto& c : result.box_corners) corner_keys.push_back(order.key_of(c[0], c[1], c[2]));
                keys.insert(keys.begin(), corner_keys.begin(), corner_keys.end());
            }
            tri.set_curve_keys(std::move(keys));
        }
        const index_t base = tri.point_count() - static_cast<index_t>(n);
        result.stats.seconds_order = seconds_since(t_start);

        const auto t_insert = Clock::now();
        tri.reserve_tets(static_cast<std::size_t>(kTetsPerPoint * double(n + 8)) + 64);
        // Round r holds kernel ids [round_begin[r], round_begin[r+1]); the box corners join
        // the first round.
        std::vector<index_t> round_begin(order.round_begin.begin(), order.round_begin.end());
        for (index_t& k : round_begin) k += base;
        round_begin.front() = 0;
        const auto round = [&](std::size_t r) {
            std::vector<index_t> ids(round_begin[r + 1] - round_begin[r]);
            std::iota(ids.begin(), ids.end(), round_begin[r]);
            return ids;
        };
        std::vector<index_t> used;
        if (round_begin.size() > 1) used = tri.start(round(0));
        if (used.empty() && tri.point_count() >= 4) {  // the first round is flat: try them all
            std::vector<index_t> all(tri.point_count());
            std::iota(all.begin(), all.end(), index_t{0});
            used = tri.start(all);
        }
        if (!used.empty()) {
            std::sort(used.begin(), used.end());
            for (std::size_t r = 0; r + 1 < round_begin.size(); ++r) {
                std::vector<index_t> ids = round(r);
                std::erase_if(ids, [&](index_t k) { return std::binary_search(used.begin(), used.end(), k); });
                tri.insert(ids, parts, options.min_points_per_part);
            }
        }
        result.stats.seconds_insert = seconds_since(t_insert);

        const auto t_finish = Clock::now();
        if (tri.started()) {
            result.tets = tri.finish();
            result.duplicates = tri.duplicates();
        }
        result.stats.seconds_finish = seconds_since(t_finish);
        const KernelCounters& c = tri.counters();
        result.stats.passes = c.passes;
        result.stats.conflicts = c.conflicts;
        result.stats.walk_conflicts = c.walk_conflicts;
        result.stats.postponed_no_room = c.no_room;
        result.stats.serial_insertions = c.serial_inserted;
        result.stats.walk_steps = c.walk_steps;
        result.stats.seconds_passes = c.seconds_passes;
        result.stats.seconds_serial = c.seconds_serial;
        result.stats.peak_bytes = tri.peak_bytes();
    }
    result.stats.tets = result.tets.size();
    result.stats.duplicates = static_cast<index_t>(result.duplicates.size());
    result.stats.bytes_per_tet =
        result.stats.tets ? double(result.stats.peak_bytes) / double(result.stats.tets) : 0.0;
    result.stats.seconds_total = seconds_since(t_start);
    return result;
}

}  // namespace tubemesh::delaunay
