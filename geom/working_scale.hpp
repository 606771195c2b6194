#pragma once
// Meshing is scale-free: a model is meshed in a working space where its bounding-box diagonal
// lies in [1, 1000), the range the mesher's tolerances are set for. The factor is a power of
// ten, 10^k with k a multiple of 3 (the engineering prefixes: a part drawn in micrometres,
// millimetres or kilometres lands on the same working model), so a model already in that range
// (every reference case: diagonals 19.6 to 514) is meshed exactly as given. The Model keeps k;
// the mesh, its report and every length a user sees are scaled back by 10^k.
// The factor itself: geom/model/scale_factor.hpp. No OpenCASCADE header here.
#include <optional>
#include <string>

#include "engine/pipeline/pipeline.hpp"
#include "geom/model/model.hpp"
#include "geom/model/scale_factor.hpp"
#include "geom/sizing/sizing.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

struct MeshRun;

// The model at working scale when it is not yet there (a built block or a model made in
// memory), with Model::scale_exponent the sum of both; nullopt when it already is.
std::optional<Model> working_copy(const Model& model);

// The user's lengths (S, St, the tet step's far size) in the working space of exponent k.
MeshOptions working_options(const MeshOptions& options, int k);

// The figures of a tube search and a size plan back from the working space (the reasons and
// warnings are text and stay as they were written).
TubeSearch at_source_scale(TubeSearch tubes, int k);
SizePlan at_source_scale(SizePlan plan, int k);

// The line a report adds when the model was meshed scaled (k != 0): what was done, and which
// lengths are still the working space's.
std::string working_scale_line(int k);

// Back from the working space: mesh coordinates, the check's volume and area, the phases'
// lengths, areas and volumes, the rings' lengths, S and St. Nothing to do for k = 0.
void scale_back(MeshRun& run, int k);

}  // namespace tubemesh::geom
