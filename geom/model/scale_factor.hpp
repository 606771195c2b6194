#pragma once
// The power of ten a model is meshed at (geom/working_scale.hpp says why): the factor and the
// conversions, used by the readers as well as by the run. No OpenCASCADE header here
// (scale_factor_occt.hpp has the shape side).

namespace tubemesh::geom {

// k, a multiple of 3, with diagonal / 10^k in [1, 1000); 0 for a diagonal that is not a
// positive finite number.
int working_scale_exponent(double diagonal);

// length · 10^-k (into the working space) and length · 10^k (back), each one correctly
// rounded operation with the exact power 10^|k|.
double to_working(double length, int k);
double from_working(double length, int k);

}  // namespace tubemesh::geom
