#pragma once
// From a geom::Model to the engine's PipelineInput: find_tubes -> plan_sizes (with the user's
// S / St) -> discretize -> one SurfaceMap per face. The PreparedModel owns all of it (the
// maps keep their own handles to the geometry, so it does not need the Model afterwards).
//
// No OpenCASCADE header here.
#include <memory>
#include <string>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/model.hpp"
#include "geom/sizing.hpp"
#include "geom/tubes.hpp"

namespace tubemesh::geom {

struct PrepareOptions {
    SizingOptions sizing;  // S and St; 0 picks geom's defaults (sizing.hpp)
    TubeOptions tubes;
};

class PreparedModel {
public:
    TubeSearch tubes;
    SizePlan plan;
    DiscreteGeometry geometry;
    std::vector<std::unique_ptr<SurfaceMap>> maps;  // element i: face id i + 1

    // Refers to this object: valid while it lives and is not moved.
    PipelineInput pipeline_input() const;
    // What a user should know before meshing: tubes found and not, S and St and every change
    // the sizing rules made, warnings. One line each, no trailing newline.
    std::vector<std::string> report_lines() const;
};

// Throws tubemesh::Error for bad user sizes or geometry that cannot be discretised.
PreparedModel prepare_model(const Model& model, const PrepareOptions& options = {});

}  // namespace tubemesh::geom
