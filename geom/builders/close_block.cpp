#include "geom/builders/close_block.hpp"

#include <cmath>
#include <string>

#include "geom/builders/random.hpp"

namespace tubemesh::geom {

namespace {

double round_to(double v, double step) { return std::round(v / step) * step; }

// A gap between walls, relative to the radius r.
double gap(double r, bool may_cross, Random& rng) {
    const double pick = rng.uniform(0, 1);
    if (pick < 0.1) return 0;
    if (may_cross && pick < 0.2) return -r * rng.uniform(0.1, 1.5);
    return r * std::pow(10.0, rng.uniform(-3, 0.5));
}

}  // namespace

BlockSpec close_block_spec(std::uint64_t seed) {
    Random rng(seed);
    BlockSpec spec;
    spec.name = "close seed " + std::to_string(seed);
    spec.check_clearance = false;
    const Vec3 size{round_to(rng.uniform(3, 6), 0.5), round_to(rng.uniform(3, 6), 0.5), round_to(rng.uniform(3, 6), 0.5)};
    spec.host.size = size;
    const double d1 = round_to(rng.uniform(0.1, 0.3), 0.01), d2 = round_to(rng.uniform(0.1, 0.3), 0.01);
    const double r1 = d1 / 2, r2 = d2 / 2;

    const double y1 = size.y / 2 + rng.uniform(-0.5, 0.5);
    const double z1 = r1 + gap(r1, false, rng);
    PipeSpec a;
    a.kind = PathKind::Line;
    a.diameter = d1;
    a.points = {{0, y1, z1}, {size.x, y1, z1}};
    spec.pipes.push_back(a);

    const double z2 = z1 + r1 + r2 + gap(std::min(r1, r2), true, rng);
    PipeSpec b;
    b.kind = PathKind::Line;
    b.diameter = d2;
    if (rng.integer(0, 1) == 0) {
        b.points = {{0, y1, z2}, {size.x, y1, z2}};  // parallel, above pipe 1
    } else {
        const double x = size.x / 2 + rng.uniform(-0.5, 0.5);
        b.points = {{x, 0, z2}, {x, size.y, z2}};  // across pipe 1
    }
    spec.pipes.push_back(b);
    return spec;
}

}  // namespace tubemesh::geom
