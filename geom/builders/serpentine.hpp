#pragma once
// Serpentine cooling loops of a concrete dam lift: one pipe running back and forth across the
// lift at mid-height (or at a given height, as pipes laid on a lift joint are), U-bends at the
// ends, entering and leaving through side faces.
#include <string>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

struct SerpentineParams {
    Vec3 size{20, 15, 3};     // the lift: x by y, height z
    double diameter = 0.032;  // of the pipe
    double spacing = 1.5;     // between neighbouring runs
    double bend_radius = 0.75;  // of the U-bends; at most spacing / 2
    double end_margin = 1.0;    // from the outermost point of a bend's centre line to the face
    // The pipe's centre above the lift's bottom, in pipe radii; 0: at mid-height. Above 1, and the
    // pipe below the top.
    double height_radii = 0;
    // Side faces: "x-", "x+", "y-" or "y+". The runs go along the inlet's axis; the outlet is on
    // the same face (an even number of runs) or the opposite one (odd).
    std::string inlet = "x-";
    std::string outlet = "x-";
    std::string length_unit = "metre";
};

// As many runs as fit `spacing` apart with half a spacing to the side faces, one fewer when the
// parity does not match the outlet. Throws tubemesh::Error on parameters that do not fit.
BlockSpec serpentine_spec(const SerpentineParams& params, const std::string& name = "serpentine");

}  // namespace tubemesh::geom
