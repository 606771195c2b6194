#pragma once
// Several solids that share faces meshed into one conforming hybrid mesh (docs/architecture.md,
// "Beyond one solid"), face first:
//  * the sweep and the surface run once over the whole assembly (run_pipeline up to Surface):
//    every tube's ring, then every face that is not a tube wall triangulated once, a face two
//    solids share included;
//  * then each solid's pyramids and tets against its now fixed boundary (its faces' triangles,
//    those of a face it sees reversed turned round), the solids side by side on the threads,
//    each in a mesh of its own that is merged back in solid order, so the result is the same
//    for any thread count.
// A pipe that crosses from one solid into the next is two tubes whose rings are joined on the
// shared face (PipelineInput::ring_joins): one cross-section there, one wall group.
// The cells' regions are the solids (region k = solid k, named after it); a shared face's
// triangles and ring end quads are interior faces of the result, in the interface group
// "joint_<A>_<B>" of its two solids (hybrid_mesh.hpp).
#include <string>
#include <vector>

#include "engine/pipeline/pipeline.hpp"

namespace tubemesh {

struct AssemblySolidInput {
    std::string name;
    // The B-rep faces bounding the solid (ids of the whole input), and for each whether the
    // solid sees it opposite to its SurfaceMap (the other solid of a shared face).
    std::vector<index_t> faces;
    std::vector<char> reversed;
    std::vector<index_t> tubes;  // indices into the geometry's tubes: the tubes inside this solid
};

struct AssemblyInput {
    PipelineInput whole;  // every face once, every tube (geom/assembly/mesh_assembly.hpp)
    std::vector<AssemblySolidInput> solids;
};

// What one solid holds after the run.
struct SolidSummary {
    std::string name;
    index_t hexes = 0, pyramids = 0, tets = 0;
    index_t nodes = 0;  // of its cells, those on its shared faces included
    QualitySummary quality;
    double volume = 0;  // of its cells (check_mesh's volumes)
    // Its pyramids and its tets, each on the thread it had; the sweep and the surface are the
    // whole assembly's.
    double pyramid_seconds = 0, tet_seconds = 0;
    tets::TetStepStats tet_stats;
};

struct AssemblyResult {
    PipelineResult result;  // the one mesh; phases sweep, surface, pyramids, tets
    std::vector<SolidSummary> solids;
    index_t shared_triangles = 0;  // triangles on the shared faces (joint groups)
};

// Throws tubemesh::Error from the first phase that fails, naming the solid.
AssemblyResult run_assembly(const AssemblyInput& input, const MeshOptions& options = {});

}  // namespace tubemesh
