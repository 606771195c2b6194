#include "engine/sweep/centre_line.hpp"

#include <algorithm>
#include <cmath>
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

}  // namespace

CentreLine resample_centre_line(std::span<const TubeStation> input, double step, const Vec3& first_node) {
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

    const int layers = std::max(1, static_cast<int>(std::lround(line.length / step)));
    line.stations.reserve(static_cast<std::size_t>(layers) + 1);
    std::size_t seg = 0;
    for (int i = 0; i <= layers; ++i) {
        Station st;
        if (i == 0) {
            st = exact(input.front());
        } else if (i == layers) {
            st = exact(input.back());
        } else {
            const double s = line.length * i / layers;
            while (seg + 2 < input.size() && at[seg + 1] <= s) ++seg;
            const double chord = at[seg + 1] - at[seg];
            st = between(input[seg], input[seg + 1], chord, std::clamp((s - at[seg]) / chord, 0.0, 1.0));
        }
        st.s = line.length * i / layers;
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
