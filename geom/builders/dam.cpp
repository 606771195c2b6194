#include "geom/builders/dam.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "engine/core/types.hpp"
#include "geom/builders/random.hpp"
#include "geom/builders/serpentine.hpp"

namespace tubemesh::geom {

namespace {

// Values read better in a manifest rounded to millimetres (and tenths of one for diameters).
double round_to(double v, double step) { return std::round(v / step) * step; }

double draw(Random& rng, const Range& r, double step) { return round_to(rng.uniform(r.lo, r.hi), step); }

void check_range(const Range& r, const char* name, double at_least) {
    if (!(r.lo >= at_least && r.hi >= r.lo && std::isfinite(r.hi)))
        throw Error(fmt::format("dam {} range {}:{} must satisfy {} <= min <= max", name, r.lo, r.hi, at_least));
}

// Mirrors the pipe across the block's mid-plane x = width / 2: the inlet at the other end of
// the downstream face.
void mirror_x(PipeSpec& pipe, double width) {
    for (Vec3& p : pipe.points) p.x = width - p.x;
}

// The pieces of the crossing pipes (DamParams::crossing_pipes): in lift l, a straight pipe at
// y = half the smallest depth and z a quarter up the lift's height common to all its columns,
// of the lift's smallest serpentine diameter.
void add_crossing_pipes(std::vector<DamBlock>& blocks, const DamParams& p) {
    if (p.crossing_pipes < 0 || p.crossing_pipes > p.lifts)
        throw Error(fmt::format("a dam of {} lifts takes 0 to {} crossing pipes, one per lift", p.lifts, p.lifts));
    for (int k = 0; k < p.crossing_pipes; ++k) {
        const int lift = 1 + k * p.lifts / p.crossing_pipes;
        double lo = -std::numeric_limits<double>::infinity(), hi = -lo, depth = hi, diameter = p.diameter.lo;
        bool drawn = false;
        for (const DamBlock& b : blocks) {
            if (b.lift != lift) continue;
            lo = std::max(lo, b.origin.z);
            hi = std::min(hi, b.origin.z + b.spec.host.size.z);
            depth = std::min(depth, b.spec.host.size.y);
            for (const PipeSpec& pipe : b.spec.pipes) {
                diameter = drawn ? std::min(diameter, pipe.diameter) : pipe.diameter;
                drawn = true;
            }
        }
        if (!(hi > lo))
            throw Error(fmt::format("the blocks of lift {} share no height across the columns: no pipe can cross "
                                    "them (give the lifts one height)", lift));
        const double z = lo + (hi - lo) / 4, y = depth / 2;
        for (DamBlock& b : blocks) {
            if (b.lift != lift) continue;
            PipeSpec piece;
            piece.kind = PathKind::Line;
            piece.diameter = diameter;
            piece.points = {{0, y, z - b.origin.z}, {b.spec.host.size.x, y, z - b.origin.z}};
            b.spec.pipes.push_back(piece);
        }
    }
}

}  // namespace

std::vector<DamBlock> dam_blocks(const DamParams& p) {
    if (p.columns < 1 || p.lifts < 1) throw Error("a dam needs at least one column and one lift");
    check_range(p.width, "width", 1e-3);
    check_range(p.depth, "depth", 1e-3);
    check_range(p.lift_height, "lift height", 1e-3);
    check_range(p.diameter, "pipe diameter", 1e-6);
    check_range(p.spacing, "run spacing", 1e-3);
    check_range(p.bend_share, "bend share", 0.05);
    if (p.bend_share.hi > 0.5) throw Error("dam bend share must be at most 0.5 of the run spacing");

    Random rng(p.seed);
    const int column_digits = static_cast<int>(std::to_string(p.columns).size());
    const int lift_digits = static_cast<int>(std::to_string(p.lifts).size());
    const bool pipeless_ends = p.pipeless_ends && p.columns * p.lifts >= 3;
    std::vector<DamBlock> blocks;
    double x = 0;
    for (int c = 1; c <= p.columns; ++c) {
        const double width = draw(rng, p.width, 1e-3), depth = draw(rng, p.depth, 1e-3);
        double z = 0;
        for (int l = 1; l <= p.lifts; ++l) {
            DamBlock b;
            b.column = c;
            b.lift = l;
            b.id = fmt::format("c{:0{}}-l{:0{}}", c, column_digits, l, lift_digits);
            b.origin = {x, 0, z};
            const double height = draw(rng, p.lift_height, 1e-3);
            SerpentineParams s;
            s.size = {width, depth, height};
            s.diameter = draw(rng, p.diameter, 1e-4);
            s.spacing = draw(rng, p.spacing, 1e-3);
            s.bend_radius = round_to(s.spacing * rng.uniform(p.bend_share.lo, p.bend_share.hi), 1e-3);
            s.end_margin = s.spacing / 2;
            s.inlet = s.outlet = "y+";
            s.height_radii = p.pipe_height_radii;
            const bool mirrored = rng.integer(0, 1) == 1;
            if (pipeless_ends && ((c == 1 && l == 1) || (c == p.columns && l == p.lifts))) {
                b.role = l == 1 ? "foundation" : "crest";
                b.spec.name = b.id;
                b.spec.length_unit = s.length_unit;
                b.spec.host.size = s.size;
            } else {
                b.role = "lift";
                b.spec = serpentine_spec(s, b.id);
                if (mirrored) mirror_x(b.spec.pipes.front(), width);
            }
            blocks.push_back(std::move(b));
            z += height;
        }
        x += width;
    }
    add_crossing_pipes(blocks, p);
    return blocks;
}

}  // namespace tubemesh::geom
