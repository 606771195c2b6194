#include "engine/sweep/centre_line.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/sweep/frames.hpp"

namespace tubemesh::sweep {
namespace {

// sin(30°): a reference closer than this to its tangent cannot define angle 0 reliably.
constexpr double kMinReferenceSine = 0.5;

bool usable_reference(const TubeStation& st) {
    const Vec3 t = normalized(st.tangent), r = st.reference;
    if (!all_finite(r) || !all_finite(t)) return false;
    const double len = norm(r);
    return len > 0 && norm(r - dot(t, r) * t) >= kMinReferenceSine * len;
}

Vec3 orthonormal_to(const Vec3& v, const Vec3& t) {
    const Vec3 p = v - dot(t, v) * t;
    return normalized(p);
}

// Station at fraction u of the segment from a to b, `chord` apart.
Station between(const TubeStation& a, const TubeStation& b, double chord, double u) {
    const Vec3 ca = a.centre, cb = b.centre;
    const Vec3 ta = normalized(a.tangent) * chord, tb = normalized(b.tangent) * chord;
    const double u2 = u * u, u3 = u2 * u;
    Station s;
    s.centre = (2 * u3 - 3 * u2 + 1) * ca + (u3 - 2 * u2 + u) * ta + (-2 * u3 + 3 * u2) * cb + (u3 - u2) * tb;
    const Vec3 d = (6 * u2 - 6 * u) * ca + (3 * u2 - 4 * u + 1) * ta + (-6 * u2 + 6 * u) * cb + (3 * u2 - 2 * u) * tb;
    s.tangent = normalized(d);
    s.reference = orthonormal_to((1 - u) * a.reference + u * b.reference, s.tangent);
    s.radius = (1 - u) * a.radius + u * b.radius;
    return s;
}

Station exact(const TubeStation& a) {
    Station s;
    s.centre = a.centre;
    s.tangent = normalized(a.tangent);
    s.reference = a.reference;
    s.radius = a.radius;
    return s;
}

// Station positions along a line of this length where the wanted step is local_step(s) (at most
// `step`, positive): the whole number of steps nearest to the integral of 1 / local_step, each
// step taking an equal share of that integral, so the spacing follows the wanted step and
// changes as smoothly as it does.
std::vector<double> graded_positions(double length, double step, const std::function<double(double)>& local_step) {
    // Fine enough that a step's share of the integral is found to a small part of it.
    const int samples = std::clamp(static_cast<int>(std::ceil(16 * length / step)), 16, 1 << 20);
    std::vector<double> at(static_cast<std::size_t>(samples) + 1), sum(at.size(), 0.0);
    double before = 1.0 / std::clamp(local_step(0.0), 1e-12 * step, step);
    for (int k = 0; k <= samples; ++k) {
        at[static_cast<std::size_t>(k)] = length * k / samples;
        if (k == 0) continue;
        const double now = 1.0 / std::clamp(local_step(at[static_cast<std::size_t>(k)]), 1e-12 * step, step);
        sum[static_cast<std::size_t>(k)] = sum[static_cast<std::size_t>(k) - 1] + 0.5 * (before + now) * (length / samples);
        before = now;
    }
    const int layers = std::max(1, static_cast<int>(std::lround(sum.back())));
    std::vector<double> where{0.0};
    std::size_t k = 0;
    for (int i = 1; i < layers; ++i) {
        const double target = sum.back() * i / layers;
        while (k + 1 < sum.size() && sum[k + 1] < target) ++k;
        const double span = sum[k + 1] - sum[k];
        const double u = span > 0 ? (target - sum[k]) / span : 0.0;
        where.push_back(at[k] + u * (at[k + 1] - at[k]));
    }
    where.push_back(length);
    return where;
}

}  // namespace

CentreLine resample_centre_line(std::span<const TubeStation> input, double step, const Vec3& first_node,
                                 const std::function<double(double)>& local_step) {
    if (input.size() < 2) throw Error("the centre line has fewer than two stations");
    std::vector<double> at(input.size(), 0.0);  // chord length from the first station
    for (std::size_t i = 0; i < input.size(); ++i) {
        const Vec3 t = input[i].tangent;
        if (!(norm(t) > 0) || !all_finite(t)) throw Error("centre-line station " + std::to_string(i) + " has no tangent");
        if (i == 0) continue;
        const double chord = norm(input[i].centre - input[i - 1].centre);
        if (!(chord > 0)) throw Error("centre-line stations " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                      " coincide");
        at[i] = at[i - 1] + chord;
    }
    CentreLine line;
    line.length = at.back();
    line.frame_fallback = !std::all_of(input.begin(), input.end(), usable_reference);

    const std::vector<double> where = local_step ? graded_positions(line.length, step, local_step)
                                                 : std::vector<double>{};
    const int layers = local_step ? static_cast<int>(where.size()) - 1
                                  : std::max(1, static_cast<int>(std::lround(line.length / step)));
    const auto position = [&](int i) { return local_step ? where[static_cast<std::size_t>(i)] : line.length * i / layers; };
    line.stations.reserve(static_cast<std::size_t>(layers) + 1);
    std::size_t seg = 0;
    for (int i = 0; i <= layers; ++i) {
        Station st;
        if (i == 0) {
            st = exact(input.front());
        } else if (i == layers) {
            st = exact(input.back());
        } else {
            const double s = position(i);
            while (seg + 2 < input.size() && at[seg + 1] <= s) ++seg;
            const double chord = at[seg + 1] - at[seg];
            st = between(input[seg], input[seg + 1], chord, std::clamp((s - at[seg]) / chord, 0.0, 1.0));
        }
        st.s = position(i);
        if (!line.frame_fallback) st.reference = orthonormal_to(st.reference, st.tangent);
        line.stations.push_back(st);
    }
    line.stations.back().s = line.length;

    if (line.frame_fallback) {
        std::vector<Vec3> centres, tangents;
        for (const Station& st : line.stations) {
            centres.push_back(st.centre);
            tangents.push_back(st.tangent);
        }
        const std::vector<Frame> frames =
            rotation_minimizing_frames(centres, tangents, first_node - line.stations.front().centre);
        for (std::size_t i = 0; i < frames.size(); ++i) line.stations[i].reference = frames[i].normal;
    }
    return line;
}

}  // namespace tubemesh::sweep
