#pragma once
// Sizes for the narrow gaps beside holes that are not tubes (meshed with tets): where such a
// hole's wall passes a face it does not touch closer than S, the faces on both sides of the gap
// get triangles no larger than the gap, so the tets across it are not slivers and boundary
// recovery can find them. (A tube's ring is thinned by the sizing rules instead.) A gap under
// kThinnestRing of the hole's radius (a pipe touching a face) gets that size, not its own: the
// tets there are flat, and the run warns of it (geometry_diagnosis.hpp).
//
// No OpenCASCADE header here.
#include <vector>

#include "engine/sizing/field/size_field.hpp"
#include "geom/model/model.hpp"
#include "geom/sizing/sizing_distances.hpp"

namespace tubemesh::geom {

// Sources at the hole walls' points (a grid a quarter of the radius apart) whose distance d to
// a near face is below `size`, and at their feet on that face, each of size d (at least
// kThinnestRing of the radius); without those that others make redundant in a size field of
// growth `growth` (the field is the same without them).
std::vector<SizeSource> gap_size_sources(const Model& model, const std::vector<HoleGroup>& holes, double size,
                                         double growth);

}  // namespace tubemesh::geom
