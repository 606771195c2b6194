#include "engine/sweep/ring_room.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::sweep {
namespace {

// Sample i's thickness towards dir, periodic-linear between its D directions.
double around(const RingRoom& room, std::size_t i, const Vec3& dir) {
    const Vec3& t = room.tangent[i];
    const Vec3& u = room.u[i];
    const Vec3 v = cross(t, u);
    double phi = std::atan2(dot(dir, v), dot(dir, u));
    if (phi < 0) phi += 2 * std::numbers::pi;
    const int d = room.directions;
    const double x = phi / (2 * std::numbers::pi) * d;
    const int k0 = std::min(static_cast<int>(std::floor(x)), d - 1);
    const double w = std::clamp(x - k0, 0.0, 1.0);
    const double* row = room.thickness.data() + i * static_cast<std::size_t>(d);
    return (1 - w) * row[k0] + w * row[(k0 + 1) % d];
}

}  // namespace

double room_thickness(const RingRoom& room, double s, const Vec3& dir) {
    if (room.empty()) return std::numeric_limits<double>::infinity();
    const auto& ss = room.s;
    if (ss.size() == 1 || s <= ss.front()) return around(room, 0, dir);
    if (s >= ss.back()) return around(room, ss.size() - 1, dir);
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(ss.begin(), ss.end(), s) - ss.begin()) - 1;
    const double span = ss[i + 1] - ss[i];
    const double w = span > 0 ? (s - ss[i]) / span : 0.0;
    return (1 - w) * around(room, i, dir) + w * around(room, i + 1, dir);
}

double room_scale(const RingRoom& room, double sweep_size, double s, const Vec3& dir) {
    if (room.empty()) return 1.0;
    return std::min(1.0, room_thickness(room, s, dir) / sweep_size);
}

double thinnest_at(const RingRoom& room, double s) {
    if (room.empty()) return std::numeric_limits<double>::infinity();
    const auto& ss = room.s;
    const std::size_t d = static_cast<std::size_t>(room.directions);
    const auto row_min = [&](std::size_t i) {
        return *std::min_element(room.thickness.begin() + static_cast<std::ptrdiff_t>(i * d),
                                 room.thickness.begin() + static_cast<std::ptrdiff_t>((i + 1) * d));
    };
    if (ss.size() == 1 || s <= ss.front()) return row_min(0);
    if (s >= ss.back()) return row_min(ss.size() - 1);
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(ss.begin(), ss.end(), s) - ss.begin()) - 1;
    const double span = ss[i + 1] - ss[i];
    const double w = span > 0 ? (s - ss[i]) / span : 0.0;
    return (1 - w) * row_min(i) + w * row_min(i + 1);
}

double thinnest(const RingRoom& room) {
    if (room.empty()) return std::numeric_limits<double>::infinity();
    return *std::min_element(room.thickness.begin(), room.thickness.end());
}

}  // namespace tubemesh::sweep
