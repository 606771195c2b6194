#pragma once
// The options of one meshing run as a user gives them: `tubemesh mesh`'s flags and the Python
// module's keywords. One struct, one validation, one translation into MeshOptions, so the two
// front ends take the same values with the same defaults and refuse the same ones with the
// same message. Defaults are MeshOptions' own (engine/pipeline/pipeline.hpp documents each);
// an empty optional is "automatic".
#include <optional>
#include <string>

#include "engine/pipeline/pipeline.hpp"

namespace tubemesh::run {

// The documented defaults every field below starts from.
const MeshOptions& default_mesh_options();

struct MeshSettings {
    std::optional<double> size;             // S; automatic: bounding-box diagonal / 25, >= 1.3 St
    std::optional<double> sweep_size;       // St; automatic: smallest tube diameter, cut by the rules
    std::optional<int> circumferential;     // n; automatic: multiple of 4 nearest 2 pi (r + St/2) / St, >= 8
    int layers = default_mesh_options().sweep.radial_layers;
    double axial_aspect = default_mesh_options().sweep.axial_aspect;
    double pyramid_height = default_mesh_options().pyramids.height_factor;
    double gradation = default_mesh_options().tets.gradation;
    std::optional<int> threads;             // automatic: all cores
    int tet_parts = static_cast<int>(default_mesh_options().tet_parts);
    int tet_relax = default_mesh_options().tets.relaxation.iterations;
    bool move_apexes = default_mesh_options().tets.move_apexes;
    std::optional<double> max_elements;     // automatic: what this machine's memory holds
    std::optional<int> solid;               // which solid of the file, 1-based; automatic: the only one
    Stage until = kLastStage;
};

// The ranges the front ends accept (inclusive).
struct Range {
    double lo, hi;
};
// A ring needs 4 nodes around at least. More layers than 8 make the innermost hexes too thin
// for the analysis limit (condition number 4) at any axial step: 6 already gives 4.6 on the
// dam block.
inline constexpr Range kCircRange{4, 4096};
inline constexpr Range kLayersRange{1, 8};
inline constexpr Range kAxialAspectRange{0.25, 16.0};
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

}  // namespace tubemesh::run
