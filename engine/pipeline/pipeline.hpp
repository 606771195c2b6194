#pragma once
// The meshing pipeline (docs/architecture.md, "Data flow"): sweep -> surface -> pyramids -> tets,
// on plain data only — geom/prepare.hpp turns a CAD model into a PipelineInput.
//
//  * Sweep: a hex ring around every tube (engine/sweep), region "hex_ring"; the rings' wall
//    quads (group "pipe_<k>") and end quads (group "face_<host>") become boundary quads.
//  * Surface: the nodes of every discretised B-rep edge, then triangles on every face that is
//    not a tube wall (engine/surface), with the rings' outer polygons as holes in their host
//    faces and a size field S with point sources on those polygons. Group "face_<id>".
//  * Pyramids: one pyramid on every outer quad of the rings (engine/pyramids), region
//    "pyramids"; the surface triangles bound the region, the end quads are obstacles.
//  * Tets: the region bounded by the tet front (the pyramids' free triangles and the surface
//    triangles no pyramid covers) filled with tetrahedra (engine/tets/tet_step.hpp), region
//    "tets": boundary recovery, interior points graded from the front's sizes to S,
//    optimisation. A solid without tubes goes straight from the surface to the tets.
//
// What the mesh holds when the pipeline stops early (`until`):
//  * after Sweep: the hex rings with all their boundary faces (wall and end quads). The outer
//    quads are interior in the final mesh and are not stored: a sweep-only mesh is therefore
//    open there, and `check_mesh` reports nothing else — it is a valid, conforming cell mesh
//    whose outer quads are free cell faces (check_mesh counts them as boundary faces; they are
//    simply not in a surface group). `tubemesh check` passes on it.
//  * after Surface: + the surface triangles, stored as boundary triangles (group "face_<id>"),
//    though no cell has them yet. They are the final mesh's boundary faces; only the tets will
//    make them cell faces. check_mesh reports them as BoundaryFaceNotOnCell (and the open
//    surface of rings + triangles as nothing else): partial meshes from this stage on are for
//    looking at, not for `tubemesh check`.
//  * after Pyramids: + the pyramids. The pyramids' free triangles (the tets' front) are NOT
//    stored as boundary faces — they are interior in the final mesh — but returned in
//    PipelineResult::tet_front. Surface triangles that a pyramid face now covers stay as
//    boundary faces (they are the pyramid's free face, on the solid's boundary).
//  * after Tets: the full hybrid mesh; every boundary face is a free face of one cell, and
//    `tubemesh check` passes.
// Writers: .msh and .vtu write every partial mesh; .inp needs every boundary face on a cell
// and so refuses the surface and pyramid stages.
//
// Every phase is deterministic for a given thread count (each module guarantees it), so the
// pipeline is too.
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/check/mesh_check.hpp"
#include "engine/core/parallelism.hpp"
#include "engine/core/types.hpp"
#include "engine/core/usable_memory.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/mesh_description.hpp"
#include "engine/pipeline/element_cap.hpp"
#include "engine/pipeline/progress.hpp"
#include "engine/pyramids/build_pyramids.hpp"
#include "engine/quality/quality.hpp"
#include "engine/surface/face_mesher.hpp"
#include "engine/sizing/field/size_field.hpp"
#include "engine/sweep/ring_joins.hpp"
#include "engine/sweep/sweep.hpp"
#include "engine/tets/tet_step.hpp"

namespace tubemesh {

enum class Stage { Sweep, Surface, Pyramids, Tets };

// Every stage in pipeline order, and the last one: run_pipeline's and the CLI's default.
// (A new stage goes into the enum, stage_name and this list; nothing else keys on the count.)
inline constexpr Stage kStages[] = {Stage::Sweep, Stage::Surface, Stage::Pyramids, Stage::Tets};
inline constexpr Stage kLastStage = kStages[std::size(kStages) - 1];

const char* stage_name(Stage s);  // "sweep", "surface", "pyramids", "tets"
// The inverse of stage_name; nullopt for a name that is no stage.
std::optional<Stage> stage_from_name(std::string_view name);

// Every knob of a run, each with its default. The first three are the user's sizes: geom
// plans with them (geom/prepare.hpp, geom/mesh_file.hpp) and hands the planned S and St to the
// engine in DiscreteGeometry; run_pipeline itself reads the fields from `sweep` on.
struct MeshOptions {
    // S, the overall mesh size (edges and surface triangles far from the tubes). 0 (default):
    // the bounding-box diagonal / 25, at least 1.3 St of the final St (geom/sizing/sizing.hpp). A
    // given S is never changed.
    double size = 0;
    // St, the hex ring's thickness and axial spacing. 0 (default): the smallest tube
    // diameter, then cut by the paper's rules. A value given here is honoured or refused: if
    // the rules would have to cut it, or it is not below S, preparing the model throws.
    double sweep_size = 0;
    // > 0: when sweep_size is 0, St starts from this share of S instead of the tube diameter
    // (the economy preset); the rules still cut it. 0 (default): unused.
    double sweep_share = 0;
    // true (default): each ring thins only where a face or a tube comes near it, per place and
    // direction (geom/sizing/ring_room.hpp), with shorter steps along it there, and St stays; a
    // tube with room everywhere gets the paper's ring. false: the paper's one St for every ring,
    // cut by the rules for the closest place of all.
    bool local_ring = true;
    // > 0: geom rounds every length, position, direction and parameter it hands the engine to
    // 2^-grid_bits of the solid's diagonal (geom/engine_grid.hpp, kScaleFreeGridBits), so solids
    // that differ only by rounding (one shape drawn at 1e-6, 1 and 1e6) mesh alike. 0 (default):
    // off; the grid changes every mesh by tie-breaks.
    int grid_bits = 0;
    // n, nodes around every tube. 0 (default): the multiple of 4 nearest to the ring's
    // mid-circumference over St, at least 8 (circumferential_count in engine/sweep/sweep.hpp,
    // which says why; the paper's 4 only when given).
    int circumferential = 0;
    // How far a curved B-rep edge's chords may stray from it, as a fraction of each chord's
    // length (geom/sizing/discretize_edges.hpp). kDefaultChordal: segments turn by 0.065 rad.
    double chordal = kDefaultChordal;
    // Whether the user gave `chordal` (a front end sets it): a run whose tet step fails is then
    // not retried with a coarser tolerance but refused, naming one that works
    // (geom/mesh_file.hpp). false (default): the tolerance is the run's to change.
    bool chordal_given = false;

    // Hex ring options (engine/sweep/sweep.hpp documents each default: L = 2 layers graded
    // 1.5, axial aspect 1.5, condition cap 3.0). sweep.sweep_size = 0 (the default) takes
    // DiscreteGeometry::sweep_size, St from geom's size plan; store_boundary_faces must stay
    // true (the pipeline forces it).
    SweepOptions sweep;
    // Face mesher options (engine/surface/face_mesher.hpp: accept ratio 1.3, min spacing 0.6,
    // 3 optimisation passes).
    surface::FaceMeshOptions surface;
    // g of the size field h(x) = min(S, min_i h_i + g |x - x_i|), sources on the rings' outer
    // polygons (size_field.hpp). 0.25 by default. S is DiscreteGeometry::size.
    double size_growth = 0.25;
    // Pyramid layer options (engine/pyramids/build_pyramids.hpp: the paper's apex height
    // 0.98154 h, search radius 1.5 h, 45 degrees, distance 0.65 h, 5 try nodes, 8 drawback
    // rounds, quality floor 0.45).
    PyramidOptions pyramids;
    // Tet step options (engine/tets/tet_step.hpp and the headers it names: gradation 1.6,
    // size tolerance 1.3, 8 optimisation passes, flip threshold 0.5).
    // far_size = 0 (the default) takes S.
    tets::TetStepOptions tets;
    // oneTBB worker threads for the whole run, capped at the usable cores; 0 (default): all
    // cores. With tet_parts, resolved once at the run's entry (engine/core/parallelism.hpp).
    int threads = 0;
    // Spatial parts of the tet step's parallel Delaunay passes (recovery's kernel run,
    // refinement, relaxation). Default 2: cheap at 1 and 2 threads, and the quality bars checked
    // at one thread count then hold at all (bench/results/tuning-notes.md). 0 = one part per
    // thread (more parallel work on machines with more cores; the mesh then depends on the
    // thread count).
    unsigned tet_parts = 2;
    // Refuse, before meshing, a run whose sizes give more elements than this: a lower bound
    // from the solid's volume and area, S, St and the tubes' length (geom/sizing/element_budget.hpp).
    // 0 (default): what the memory this process may use holds (at 150 bytes per element). A
    // given limit also caps the real counts, after each stage and refinement round (element_cap.hpp).
    double max_elements = 0;
    // That memory; bytes 0 (default): usable_memory() (engine/core/usable_memory.hpp) when the
    // run starts. A caller that lowers its own address-space limit reads it first.
    UsableMemory memory;
    // Determinism: the same input and options always give the same mesh, byte for byte, for
    // any thread count (the sweep, surface and pyramid phases by construction, the tet step
    // because its Delaunay passes split into tet_parts parts whatever the thread count;
    // tet_parts = 0 trades this for one part per thread). There is no faster
    // timing-dependent mode.
    // Run the validity and conformity check (engine/pipeline/stage_check.hpp) as run_pipeline's
    // last stage, so every caller gets a checked mesh; it throws when the mesh fails. Default true.
    bool check = true;
    // Progress of each phase (progress.hpp); empty (default) = silent. The mesh does not
    // depend on it.
    ProgressCallback progress;
};

// One B-rep face of the model.
struct PipelineFace {
    index_t id = 0;          // B-rep face id (1-based)
    bool tube_wall = false;  // a tube's lateral face: the hex ring covers it, no triangles
};

struct PipelineInput {
    const DiscreteGeometry& geometry;
    SurfaceLookup surfaces;           // face id -> its SurfaceMap (must outlive run_pipeline)
    std::vector<PipelineFace> faces;  // every face of the model, in id order
    // Sizes the geometry asks for at points the rings and the faces' curvature do not see: the
    // narrow gaps between a hole that is not a tube and a face it passes (geom/sizing/gap_sizes.hpp).
    std::vector<SizeSource> gap_sizes;
    // Tubes that continue through a face (an assembly's pipe crossing a joint): their rings are
    // made one there right after the sweep (engine/sweep/ring_joins.hpp). The nodes they leave
    // unused stay in the mesh; the caller drops them. Empty for one solid.
    std::vector<RingJoin> ring_joins;
    // The element budget, checked on the real counts after each stage (element_cap.hpp); none
    // by default. geom's PreparedModel fills it from its estimate and limit.
    ElementCap cap;
};

// One phase of a run: the engine's phases (run_pipeline, the check last) and, before them,
// geom's (import, tubes, sizes, discretize). A new phase is one more entry.
struct PhaseReport {
    std::string name;  // "import", ..., "sweep", "surface", "pyramids", "check"
    double seconds = 0;
    std::vector<std::pair<std::string, double>> counts;      // whole numbers: ("hexes", 1432), ...
    std::vector<std::pair<std::string, double>> statistics;  // measures: ("min J_m", 0.92), ...
};

struct PipelineResult {
    HybridMesh mesh;
    // For the files and the report: after Sweep each pipe's rims, node sets "pipe_<k>_inlet"
    // (the wall nodes of the tube's first end, host1) and "pipe_<k>_outlet" ("pipe_<k>_ring_stop"
    // where the ring stops inside the solid: TubeData::stops), and its stations
    // (MeshDescription::pipes, for the water network); geom adds the
    // length unit and the surface groups' CAD kinds and aliases.
    MeshDescription description;
    std::vector<PhaseReport> phases;  // one per phase run, in order
    Stage reached = Stage::Sweep;
    // The report's totals, filled at the end of run_pipeline (geom::mesh_file adds its own
    // phases to `phases` and `seconds`).
    QualitySummary quality;             // per cell kind: count, min, mean, max, histogram
    double seconds = 0;                 // sum of the phases' seconds
    std::vector<std::string> warnings;  // what the user should know about this mesh, one line each
    CheckReport check;  // filled by the check stage (stage_check.hpp); empty when options.check is off
    SweepResult sweep;
    // After Surface: the local sizes the faces were meshed again with, where a first pass left
    // triangles too large for the tets beside them (tet_size_caps.hpp); empty when none was.
    std::vector<SizeSource> surface_size_caps;
    // After Tets: recovery, refinement and optimisation statistics.
    tets::TetStepStats tet_stats;
    // After Pyramids: the closed boundary of the tet region, 3 node ids per triangle, normal
    // out of the region — the pyramids' free triangles, then the surface triangles no pyramid
    // covers. Empty before.
    std::vector<index_t> tet_front;
    PyramidStats pyramid_stats;
};

// A phase that failed on a well-formed input where other sizes may succeed: the pyramids found
// no room in front of some rings, or boundary recovery gave up on a front that passed its checks.
// geom/mesh_file.hpp retries such runs with what the user did not give.
class RetryableFailure : public Error {
public:
    enum class Cause { PyramidRoom, Recovery };
    RetryableFailure(const std::string& message, Cause cause, std::vector<index_t> tubes = {},
                     std::string finding = {})
        : Error(message), cause(cause), tubes(std::move(tubes)), finding(finding.empty() ? message : finding) {}
    Cause cause;
    // PyramidRoom: the tubes (indices into DiscreteGeometry::tubes, ascending) whose rings hold the
    // fronts that found no pyramid. Empty for Recovery.
    std::vector<index_t> tubes;
    // The failure without the engine's own advice, for a caller whose advice replaces it.
    std::string finding;
};

// Runs the phases up to and including `until`, summarises the quality, then checks the mesh
// (options.check; a "check" phase last). Throws tubemesh::Error from the first phase that
// fails (its message names the tube or face; RetryableFailure where other sizes may succeed) or
// when the mesh fails the check.
// Reports progress per phase through options.progress: sweep counts tubes, surface faces,
// pyramids front quads (start and end of each phase: the modules run as one call each).
PipelineResult run_pipeline(const PipelineInput& input, const MeshOptions& options = {},
                            Stage until = kLastStage);

// The run's parallelism from options.threads and options.tet_parts (resolve_parallelism): what
// run_pipeline and the callers that do work before it (import, tube search) limit oneTBB to.
Parallelism run_parallelism(const MeshOptions& options);

}  // namespace tubemesh
