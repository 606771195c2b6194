#include "engine/sweep/ring_dimensions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/types.hpp"
#include "engine/quality/quality.hpp"
#include "engine/sweep/sweep.hpp"

namespace tubemesh {

int circumferential_count(double radius, double sweep_size) {
    if (!(radius > 0) || !std::isfinite(radius) || !(sweep_size > 0) || !std::isfinite(sweep_size))
        throw Error("circumferential node count: the tube radius (" + std::to_string(radius) +
                    ") and the sweep size St (" + std::to_string(sweep_size) + ") must be positive");
    const double around = 2 * std::numbers::pi * (radius + sweep_size / 2) / sweep_size;
    // Far beyond any real tube (a 1e6:1 radius to St): keeps the conversion defined.
    const double multiples = std::min(std::round(around / 4), 1e6);
    return std::max(8, 4 * static_cast<int>(multiples));
}

namespace sweep {

std::vector<double> radial_offsets(double sweep_size, int layers, double grading) {
    std::vector<double> o(static_cast<std::size_t>(layers) + 1, 0.0);
    const bool uniform = std::abs(grading - 1.0) < 1e-12;
    const double total = uniform ? layers : (std::pow(grading, layers) - 1) / (grading - 1);
    double thickness = sweep_size / total;  // of layer 0
    for (int j = 1; j <= layers; ++j) {
        o[j] = o[j - 1] + thickness;
        thickness *= grading;
    }
    o[layers] = sweep_size;  // exactly, whatever the rounding of the sum
    return o;
}

double straight_ring_condition(double radius, const std::vector<double>& offsets, int n, double step) {
    const double a = 2 * std::numbers::pi / n;
    double worst = 0;
    for (std::size_t j = 0; j + 1 < offsets.size(); ++j) {
        const double r0 = radius + offsets[j], r1 = radius + offsets[j + 1];
        const std::array<Vec3, 4> base{Vec3{r0, 0, 0}, Vec3{r1, 0, 0}, Vec3{r1 * std::cos(a), r1 * std::sin(a), 0},
                                       Vec3{r0 * std::cos(a), r0 * std::sin(a), 0}};
        std::array<Vec3, 8> hex;
        for (int c = 0; c < 4; ++c) {
            hex[c] = base[c];
            hex[c + 4] = {base[c].x, base[c].y, step};
        }
        worst = std::max(worst, hex_quality(hex).condition);
    }
    return worst;
}

double axial_step(double radius, const std::vector<double>& offsets, int n, double axial_aspect,
                  double max_condition) {
    const double outer_side = 2 * (radius + offsets.back()) * std::sin(std::numbers::pi / n);
    const double wanted = axial_aspect * outer_side;
    if (!(max_condition > 0)) return wanted;
    const double pyramid_floor = std::min(wanted, kMinAxialAspect * outer_side);
    const double lowest = std::min(0.25 * wanted, pyramid_floor);
    double step = wanted;
    while (step > lowest && straight_ring_condition(radius, offsets, n, step) > max_condition) step *= 0.95;
    step = std::max(step, lowest);
    // More layers or more nodes around than the defaults that no step brings under the cap:
    // shortening buys those hexes little and leaves the pyramids outer quads too short to
    // stand on. (The economy's 4 nodes around miss the cap too; their quarter step is kept.)
    const bool denser = offsets.size() > 3 || n > circumferential_count(radius, offsets.back());
    if (denser && straight_ring_condition(radius, offsets, n, step) > max_condition)
        return std::max(step, pyramid_floor);
    return step;
}

}  // namespace sweep
}  // namespace tubemesh
