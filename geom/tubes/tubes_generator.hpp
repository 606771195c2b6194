#pragma once
// A generator line of a tube's wall: the curve along the axis at one fixed position around
// it, from E1 to E2, made of isoline pieces of the wall faces it crosses (paper §3.2 uses two
// of them, half a turn apart, to find the centre line).
#include <GeomAdaptor_Curve.hxx>
#include <Geom_Curve.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <vector>

#include "geom/tubes/tubes_loop.hpp"

namespace tubemesh::geom {

struct GeneratorPiece {
    int face = 0;
    Handle(Geom_Curve) iso;   // the face's isoline at the generator's circumferential parameter
    double from = 0, to = 0;  // parameter interval on `iso`, in walking order (from E1 side)
    double length = 0;
};

// Position and derivatives with respect to sigma, the arc length fraction in [0, 1].
struct GeneratorPoint {
    gp_Pnt p;
    gp_Vec d1;  // = length * unit tangent
    gp_Vec d2;  // = length^2 * curvature vector (normal part only)
};

class Generator {
public:
    Generator(std::vector<GeneratorPiece> pieces, LoopPoint start, LoopPoint end);

    double length() const { return length_; }
    const LoopPoint& start() const { return start_; }  // on E1
    const LoopPoint& end() const { return end_; }      // on E2
    const std::vector<GeneratorPiece>& pieces() const { return pieces_; }

    GeneratorPoint at(double sigma) const;
    // The same line on copies of its curves, with caches of its own: for another thread (the
    // curves' evaluation caches may not be shared), evaluating exactly as this one does.
    Generator independent_copy() const;
    // Largest angle (radians) between the tangents on either side of a piece boundary.
    double max_kink() const;

private:
    // Arc length along a piece, tabulated at even parameter steps (8-point Gauss-Legendre per
    // step), so a point at a given arc length costs a table lookup and a few Newton steps
    // instead of GCPnts_AbscissaPoint's integration from scratch: the axis asks for thousands.
    struct Table {
        Handle(GeomAdaptor_Curve) curve;  // keeps its B-spline cache between calls
        std::vector<double> params;       // from `from` to `to`, even steps
        std::vector<double> arc;          // arc length from `from`
    };
    GeneratorPoint eval(int piece, double param) const;
    double param_at(int piece, double ds) const;

    std::vector<GeneratorPiece> pieces_;
    std::vector<Table> tables_;
    std::vector<double> starts_;  // arc length at each piece's start
    LoopPoint start_, end_;
    double length_ = 0;
};

}  // namespace tubemesh::geom
