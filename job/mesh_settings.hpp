#pragma once
// The meshing options of one run, as job_settings (job/job_settings.hpp) makes them from the
// option table's values (job/option_table.hpp) for every front end: one struct, one validation,
// one translation into MeshOptions. Defaults are MeshOptions' own (engine/pipeline/pipeline.hpp
// documents each); an empty optional is "automatic".
#include <optional>
#include <string>

#include "engine/pipeline/pipeline.hpp"

namespace tubemesh::job {

// The documented defaults every field below starts from.
const MeshOptions& default_mesh_options();

struct MeshSettings {
    std::optional<double> size;             // S; automatic: bounding-box diagonal / 25, >= 1.3 St
    std::optional<double> sweep_size;       // St; automatic: smallest tube diameter, cut by the rules
    std::optional<int> circumferential;     // n; automatic: multiple of 4 nearest 2 pi (r + St/2) / St, >= 8
    double chordal = default_mesh_options().chordal;
    bool chordal_given = false;             // the user gave chordal: a failed run is not retried coarser
    int layers = default_mesh_options().sweep.radial_layers;
    double axial_aspect = default_mesh_options().sweep.axial_aspect;
    double pyramid_height = default_mesh_options().pyramids.height_factor;
    double gradation = default_mesh_options().tets.gradation;
    std::optional<int> threads;             // automatic: all cores
    int tet_parts = static_cast<int>(default_mesh_options().tet_parts);
    int tet_relax = default_mesh_options().tets.relaxation.iterations;
    bool move_apexes = default_mesh_options().tets.move_apexes;
    bool slide_surface = default_mesh_options().tets.slide_surface;
    std::optional<double> max_elements;     // automatic: what the memory this process may use holds
    std::optional<int> solid;               // which solid of the file, 1-based; automatic: the only one
    Stage until = kLastStage;
    double sweep_share = 0;                 // > 0: automatic St = this share of S (apply_economy)
    bool local_ring = default_mesh_options().local_ring;
    bool scale_free = false;  // the engine's input on geom's grid (MeshOptions::grid_bits)
};

// The economy preset (`--economy`): the paper's own ring, 4 nodes around a pipe in 2 layers, St
// a share of S (at most 12.5 tube radii; the rules still cut it) and an axial step of about S, and curved CAD edges cut
// coarser than the default (0.16 rad a segment instead of 0.065). About half the default's
// elements; the default stays the quality-first choice. Measured in bench/results (table1-*).
struct EconomyPreset {
    int circumferential = 4;
    int layers = 2;
    double sweep_share = 0.42;
    double axial_aspect = 2;
    double chordal = 0.02;
    bool local_ring = false;  // the paper's one St, cut by its rules, as in its Table 1
};
inline constexpr EconomyPreset kEconomy{};

// The settings a user gave explicitly among those the preset sets (the others are optional:
// given when they hold a value).
struct GivenSettings {
    bool layers = false, axial_aspect = false, chordal = false;
};

// The economy preset on every setting of it the user did not give: n when automatic, St's
// share of S (used only when St is automatic), the layers, axial aspect and chordal tolerance
// unless `given`.
void apply_economy(MeshSettings& settings, GivenSettings given);

// The ranges the front ends accept (inclusive).
struct Range {
    double lo, hi;
};
// A ring needs 4 nodes around at least. More layers than 8 make the innermost hexes too thin
// for the analysis limit (condition number 4) at any axial step: 6 already gives 4.6 on the
// dam block.
inline constexpr Range kCircRange{4, 4096};
inline constexpr Range kLayersRange{1, 8};
// 0.2: a chord turning by 1.5 rad, a circle cut into 5; finer than 1e-4 asks for thousands.
inline constexpr Range kChordalRange{1e-4, 0.2};
// Below kMinAxialAspect (engine/sweep/sweep.hpp) the pyramids on the rings' outer quads crowd each other.
inline constexpr Range kAxialAspectRange{kMinAxialAspect, 16.0};
inline constexpr Range kPyramidHeightRange{0.2, 3.0};
inline constexpr Range kGradationRange{1.0, 4.0};
inline constexpr Range kThreadsRange{1, 4096};
inline constexpr Range kTetPartsRange{0, 4096};
inline constexpr Range kTetRelaxRange{0, 16};
inline constexpr Range kSolidRange{1, 1 << 30};

// How errors name an option: "--size" on the command line, "size" in Python.
enum class Naming { Flags, Keywords };
// "sweep_size" as the user wrote it: "--sweep-size" or "sweep_size".
std::string option_name(const char* keyword, Naming naming);

// The settings as MeshOptions (without a progress callback). Throws tubemesh::Error, one line
// naming the option, for a value out of its range, a size that is not a positive number, or
// St not below S.
MeshOptions mesh_options(const MeshSettings& settings, Naming naming);

// "tets" -> Stage::Tets; throws tubemesh::Error naming the stages for any other name.
Stage stage_named(const std::string& name, Naming naming);
// "sweep, surface, pyramids, tets"
std::string stage_names();

}  // namespace tubemesh::job
