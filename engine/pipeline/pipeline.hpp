#pragma once
// The meshing pipeline (DESIGN.md "Data flow"): sweep -> surface -> pyramids (-> tets, later),
// on plain data only — geom/prepare.hpp turns a CAD model into a PipelineInput.
//
//  * Sweep: a hex ring around every tube (engine/sweep), region "hex_ring"; the rings' wall
//    quads (group "pipe_<k>") and end quads (group "face_<host>") become boundary quads.
//  * Surface: the nodes of every discretised B-rep edge, then triangles on every face that is
//    not a tube wall (engine/surface), with the rings' outer polygons as holes in their host
//    faces and a size field S with point sources on those polygons. Group "face_<id>".
//  * Pyramids: one pyramid on every outer quad of the rings (engine/pyramids), region
//    "pyramids"; the surface triangles bound the region, the end quads are obstacles.
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
// Writers: .msh and .vtu write every partial mesh; .inp needs every boundary face on a cell
// and so refuses the surface and pyramid stages until tets exist.
//
// Every phase is deterministic for a given thread count (each module guarantees it), so the
// pipeline is too.
#include <string>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/geometry/tube_data.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/pyramids/build_pyramids.hpp"
#include "engine/surface/face_mesher.hpp"
#include "engine/surface/size_field.hpp"
#include "engine/sweep/sweep.hpp"

namespace tubemesh {

enum class Stage { Sweep, Surface, Pyramids };  // Tets comes later

const char* stage_name(Stage s);  // "sweep", "surface", "pyramids"

struct MeshOptions {
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
    // oneTBB worker threads for the whole run; 0 (default) lets oneTBB choose (all cores).
    int threads = 0;
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
};

struct PhaseReport {
    std::string name;  // "sweep", "surface", "pyramids"
    double seconds = 0;
    std::vector<std::pair<std::string, double>> counts;  // ("hexes", 1432), ("min J_m", 0.92), ...
};

struct PipelineResult {
    HybridMesh mesh;
    std::vector<PhaseReport> phases;  // one per phase run, in order
    Stage reached = Stage::Sweep;
    SweepResult sweep;
    // After Pyramids: the closed boundary of the tet region, 3 node ids per triangle, normal
    // out of the region — the pyramids' free triangles, then the surface triangles no pyramid
    // covers. Empty before.
    std::vector<index_t> tet_front;
    PyramidStats pyramid_stats;
};

// Runs the phases up to and including `until`. Throws tubemesh::Error from the first phase
// that fails (its message names the tube or face).
PipelineResult run_pipeline(const PipelineInput& input, const MeshOptions& options = {},
                            Stage until = Stage::Pyramids);

}  // namespace tubemesh
