#pragma once
// The numbers geom hands the engine, on a grid. A Delaunay-based mesher turns any difference in
// its input, even one in the last bit, into a different mesh (ties between equal triangles of a
// flat face are broken by that bit); rounding every length, position, direction and parameter
// the engine receives to a grid far coarser than the rounding of the B-rep itself makes models
// that differ only by that rounding (one solid read at 1e-6 and at 1e6 of its size) mesh alike.
// The grid is a power of two, so a snapped number is exact and snapping it again changes nothing.
// No OpenCASCADE header here.
#include <memory>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/sizing/field/size_field.hpp"

namespace tubemesh::geom {

// The grid `--scale-free` uses: 2^-26 of the diagonal (2.4e-7 m on the 29 m dam block, far below
// its 4 mm hex layers) is 10^4 times the rounding of a STEP file's 12 or 13 digits, so two
// readings of one solid seldom fall on either side of a step over the ~10^5 numbers of a run.
inline constexpr int kScaleFreeGridBits = 26;

class EngineGrid {
public:
    // Lengths and positions on steps of 2^-bits of the largest power of two not above the
    // model's bounding-box diagonal.
    explicit EngineGrid(double diagonal, int bits);

    double length(double x) const;
    Vec3 point(const Vec3& p) const;
    // A direction or a derivative: each component on 2^-bits of the vector's largest component.
    Vec3 vector(const Vec3& v) const;
    // A parameter of a range `extent` long (a face's uv, an edge's curve parameter).
    double parameter(double t, double extent) const;
    int bits() const { return bits_; }

private:
    int bits_;
    double step_;
};

// The discretised geometry (sizes, tubes, edge polylines) and gap sizes on the grid, in place.
void snap(DiscreteGeometry& geometry, const EngineGrid& grid);
void snap(std::vector<SizeSource>& sources, const EngineGrid& grid);

// `map` with every result (points, derivatives, projections, uv, ranges) on the grid.
std::unique_ptr<SurfaceMap> on_grid(std::unique_ptr<SurfaceMap> map, const EngineGrid& grid);

}  // namespace tubemesh::geom
