#pragma once
// The public one-call API: a CAD file (or a Model, or a built-in block) in, a checked hybrid
// mesh and its report out.
//
//   tubemesh::MeshOptions options;          // every default documented in pipeline.hpp
//   options.size = 0.6;
//   const auto run = tubemesh::geom::mesh_file("dam.step", options);
//   tubemesh::write_mesh(run.result.mesh, "dam.msh");      // engine/io/mesh_io.hpp
//   // run.result.phases: import, tubes, sizes, discretize, sweep, surface, pyramids, tets, check
//   // run.result.quality: per cell kind count, min, mean, max; run.result.seconds: total
//
// Steps: import (ImportOptions: one solid, healed) -> prepare (tube recognition, S and St,
// discretisation; geom/prepare.hpp) -> run_pipeline up to `until`, whose last stage is the
// check when options.check (engine/pipeline/stage_check.hpp). options.threads limits oneTBB for
// the whole call, import and check included. No OpenCASCADE header here.
//
// A phase that fails where other sizes may succeed (pyramids without room in front of a ring,
// boundary recovery giving up on a valid front) is run again with what the user did not give:
// thinner rings for those tubes, a coarser chordal tolerance (run_retry.hpp), and a tube whose
// ring finds no room at any St tried is meshed with tets; the result's warnings and model_lines
// say what changed. A run that succeeds the first time is never changed.
//
// Throws tubemesh::Error, one line a user can act on, for a missing or unreadable file, a file
// with no solid or several solids and no `solid` chosen, invalid or contradictory sizes, a
// phase that fails (and, where a retry was possible, failed again or needs a setting the user
// gave changed: the message names it and a value to try), or a mesh that fails the check.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/pipeline/pipeline.hpp"
#include "geom/builders/block_spec.hpp"
#include "geom/model/model.hpp"
#include "geom/tubes/ring_coverage.hpp"

namespace tubemesh::geom {

struct MeshRun {
    // The mesh and the report: phases (geom's first), quality per kind, total seconds,
    // warnings (no tube found, sizes changed by the rules, ...), the check's report.
    PipelineResult result;
    std::string source;                   // the file, or "builder: <preset>"
    std::string format;                   // "STEP", "IGES", "BREP" or "built"
    std::string name;                     // the solid's name (ImportReport::name), may be empty
    std::vector<std::string> model_lines;  // tubes found and not, S and St and every rule applied
    double size = 0;                      // S used
    double sweep_size = 0;                // St used (0 without tubes)
    std::size_t tubes = 0;
    // Per pipe: its wall's share under a hex ring, the ring's thickness range, and why it was
    // thinned or has none (geom/tubes/ring_coverage.hpp); model_lines end with the same as text.
    std::vector<RingCoverage> coverage;
};

struct MeshFileOptions {
    int solid = 0;  // which solid of the file, 1-based; 0: the file must hold exactly one
    Stage until = kLastStage;
    bool keyword_names = false;  // messages name Python keywords, not flags (ImportOptions)
};

MeshRun mesh_file(const std::filesystem::path& path, const MeshOptions& options = {},
                  const MeshFileOptions& file = {});

// A model already in memory (no "import" phase).
MeshRun mesh_model(const Model& model, const MeshOptions& options = {}, Stage until = kLastStage);

// A built-in block by preset name (geom/builders/presets.hpp; "paper-ex1" is the dam block);
// the build is the first phase, "build".
MeshRun mesh_preset(const std::string& preset, const MeshOptions& options = {}, Stage until = kLastStage);

// A block described by a spec (geom/builders/block_spec.hpp), built first ("build" phase).
MeshRun mesh_spec(const BlockSpec& spec, const MeshOptions& options = {}, Stage until = kLastStage);

}  // namespace tubemesh::geom
