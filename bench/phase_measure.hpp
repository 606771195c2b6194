#pragma once
// Measuring one pipeline phase while run_pipeline (or geom::mesh_model) runs the phases before
// it in the same call: where each phase ends, and what it adds to the mesh. phase_bench.cpp
// resets and reads the peak resident set at the ends, gate_kernels.cpp cuts callgrind's
// instruction counts there.
//
// A phase reports done == total at its end (engine/pipeline/progress.hpp); one that reports
// its parts as it goes (the tet step) may report done == total more than once, the last time
// at its very end, and one with nothing to do (total 0) also at its start. So `on_end(phase)`
// may be called more than once per phase, each time later in it: a listener must treat the
// last call as the end (overwrite a reading; sum callgrind dumps, which restart from zero).
#include <functional>
#include <string_view>
#include <utility>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "engine/pipeline/progress.hpp"

namespace tubemesh::bench {

inline ProgressCallback phase_ends(std::function<void(std::string_view phase)> on_end) {
    return [on_end = std::move(on_end)](const ProgressEvent& e) {
        if (e.done == e.total) on_end(e.phase);
    };
}

// The elements a phase adds: hexes, surface triangles, pyramids, tets.
inline double phase_elements(Stage stage, const HybridMesh& m) {
    switch (stage) {
        case Stage::Sweep: return m.cell_count(CellKind::Hex);
        case Stage::Surface: return m.face_count(FaceKind::Tri);
        case Stage::Pyramids: return m.cell_count(CellKind::Pyramid);
        case Stage::Tets: return m.cell_count(CellKind::Tet);
    }
    return 0;
}

}  // namespace tubemesh::bench
