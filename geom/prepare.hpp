#pragma once
// From a geom::Model to the engine's PipelineInput: find_tubes -> plan_sizes (with the user's
// S / St) -> discretize -> one SurfaceMap per face. The PreparedModel owns all of it (the
// maps keep their own handles to the geometry, so it does not need the Model afterwards).
//
// Sizes the user gave are honoured or refused, never silently replaced: prepare_model throws
// when the paper's rules would have to cut a given St (the message names the rule, the
// tubes or faces involved and the largest St allowed), and when St is not below S (whether
// each came from the user or from a default). A given S is never changed; a default S is
// recomputed from the final St (geom/sizing/sizing.hpp).
//
// A pipe no hex ring fits (walls that meet, a wall tangent to a face, too little room for the
// thinnest ring worth making: geom/sizing/geometry_diagnosis.hpp) is meshed like a hole that is no
// tube, with a warning, and St and S are planned from the other tubes alone; the gap between its
// wall and a near face gets triangles and tets of the gap's size (geom/sizing/gap_sizes.hpp).
// A pipe with room along most of its length but not at a spot near one end or along it keeps a
// ring on each stretch with room instead: the wall is split by a cross-section a diameter before
// the spot on each side (geom/sizing/ring_stop_place.hpp), each ring stops there with pyramids on
// its end quads, and the wall between gets tets. So do a branch that ends on another pipe's wall,
// drilled holes whose walls meet and a blind hole (geom/sizing/junction.hpp): their stretches from
// each open end stop before the junction or the bottom. The model meshed is then the split one
// (PreparedModel::split), whose face ids the mesh's groups and the retry's drops use.
//
// No OpenCASCADE header here.
#include <memory>
#include <string>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/sizing/discretize.hpp"
#include "geom/sizing/element_budget.hpp"
#include "geom/model/model.hpp"
#include "geom/sizing/sizing.hpp"
#include "geom/sizing/geometry_diagnosis.hpp"
#include "geom/tubes/ring_coverage.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

struct PrepareOptions {
    SizingOptions sizing;  // S and St; 0 picks geom's defaults (sizing.hpp)
    TubeOptions tubes;
    DiscretizeOptions discretize;  // ring_nodes = n; 0 picks circumferential_count per tube
    ElementBudget budget;          // checked right after the sizes are planned
    // Tubes meshed without a ring whatever their room, each by its wall faces, with the reason and
    // warning (the retry's, once thinner rings failed: geom/run_retry.hpp).
    std::vector<RingDrop> drop;
    // A pipe dropped for a spot keeps a ring on its longer stretch with room.
    bool stop_rings = true;
    // Where prepare_model split a wall for a ring that stops (its own, on the split model): the
    // cross-section's centre, the end of the centre line that keeps the ring, and why.
    struct StopAt {
        Vec3 centre, keep;
        double radius = 0;
        std::string reason;
    };
    std::vector<StopAt> stops;
    ProgressCallback progress;     // phases "tubes", "sizes", "discretize"; empty = silent
    double size_growth = MeshOptions{}.size_growth;  // the surface size field's, for the gap sizes
    int grid_bits = 0;  // > 0: the engine's input on a grid (MeshOptions::grid_bits, engine_grid.hpp)
};

// The user-facing part of MeshOptions (S, St, n, progress) as PrepareOptions.
PrepareOptions prepare_options(const MeshOptions& options);

class PreparedModel {
public:
    TubeSearch tubes;
    SizePlan plan;
    ElementEstimate estimate;  // the lower bound options.budget was checked on
    ElementCap cap;            // --max-elements on the real counts (engine/pipeline/element_cap.hpp); none by default
    DiscreteGeometry geometry;
    std::vector<std::unique_ptr<SurfaceMap>> maps;  // element i: face id i + 1
    std::vector<SizeSource> gap_sizes;              // geom/sizing/gap_sizes.hpp
    std::vector<PhaseReport> phases;                // "tubes", "sizes", "discretize"
    // Pipes meshed without a ring and why; `tubes` holds the tubes that keep theirs.
    std::vector<RingDrop> dropped;
    // Per pipe, with a ring or not: wall area, share under the ring, thickness, reasons. The ring
    // thickness is the plan's St per tube here; the run reads the sweep's (mesh_file.hpp).
    std::vector<RingCoverage> coverage;
    // The likely cause of a poor tet, in a few words: the narrowest gap beside a hole meshed with
    // tets when its tets are flat (under kThinnestRing of the radius), else pipe walls that meet;
    // empty when neither.
    std::string flat_tets_cause;
    // The model meshed when a ring stops: the given one with a pipe wall split where it stops;
    // null when prepare_model split nothing.
    std::shared_ptr<const Model> split;
    int splits = 0;  // how many walls prepare_model split for it (each a ring that stops)
    const Model& meshed(const Model& given) const { return split ? *split : given; }
    // What the user should be told: no tube found, S lowered by the rules, the plan's own
    // warnings. One line each.
    std::vector<std::string> warnings;

    // Refers to this object: valid while it lives and is not moved.
    PipelineInput pipeline_input() const;
    // What a user should know before meshing: tubes found and not, S and St and every change
    // the sizing rules made, warnings. One line each, no trailing newline. Figures in the
    // source's unit for a model at working scale exponent `scale_exponent` (working_scale.hpp).
    std::vector<std::string> report_lines(int scale_exponent = 0) const;
};

// The lower bound on the elements a run at the plan's sizes makes (element_budget.hpp), the
// figure prepare_model checks against options.budget, without the check: `inspect` shows it.
ElementEstimate estimate_run_elements(const Model& model, const TubeSearch& tubes, const SizePlan& plan,
                                      const PrepareOptions& options = {});

// Throws tubemesh::Error for bad user sizes, sizes that give more elements than
// options.budget allows (before any phase allocates for them), or geometry that cannot be
// discretised.
PreparedModel prepare_model(const Model& model, const PrepareOptions& options = {});

}  // namespace tubemesh::geom
