#pragma once
// The reference cases, shared by the per-phase benchmarks (phase_bench.cpp), the
// whole-pipeline benchmark (pipeline_bench.cpp), the peers' table (tet_step_bench.cpp) and the
// regression gate (gate_kernels.cpp):
// the paper's three examples at the sizes of their CLI acceptance (S = 0.6, 1.1, 40), the
// serpentine dam lift at its default size, the built-in dam block (paper-ex1 at its default
// size: what `tubemesh mesh` without input meshes), and a large lift (the
// serpentine lift at S = 0.11:
// about 6 million elements, minutes per run; its benchmarks carry "large-lift" in their names
// so quick runs filter them out).
//
// Blocks are built by geom's builders (OpenCASCADE), once per process and preset; preparing a
// case (tube recognition, sizes, discretisation) is done once per case and size. Neither is
// ever inside a timed or counted region.
#include <span>
#include <string>
#include <string_view>

#include "engine/pipeline/pipeline.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/prepare.hpp"

namespace tubemesh::bench {

// The large lift's name: runs that must stay short leave it out unless it is named.
inline constexpr char kLargeLift[] = "large-lift";

struct ReferenceCase {
    const char* name;    // benchmark name part: "paper-ex1", ..., "large-lift"
    const char* preset;  // geom builders' preset (geom/builders/presets.hpp)
    double size;         // S; 0 = geom's default
};

std::span<const ReferenceCase> reference_cases();

// Throws tubemesh::Error for a name that is no reference case.
const ReferenceCase& reference_case(std::string_view name);

// The case's block, built on first use and kept for the life of the process.
const geom::BuiltBlock& built_block(const ReferenceCase& c);

// MeshOptions for the case: its S, `threads` oneTBB threads (0: all cores).
MeshOptions case_options(const ReferenceCase& c, int threads);

// The case prepared for run_pipeline. Only the latest case is kept (the large lift's
// discretisation is not small): a reference from an earlier call is invalid after a call for
// another case.
const geom::PreparedModel& prepared_case(const ReferenceCase& c);

}  // namespace tubemesh::bench
