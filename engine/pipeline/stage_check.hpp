#pragma once
// The check a pipeline result must pass before anything is written (docs/architecture.md:
// the mesh passes the conformity and validity check before any file is written).
//
// check_mesh (engine/check/mesh_check.hpp) on the whole mesh, with what each stage may
// legitimately lack (pipeline.hpp, "What the mesh holds when the pipeline stops early"):
//  * after the sweep, and after any stage past the pyramids (the tets): nothing — every
//    violation fails.
//  * after surface or pyramids: the surface triangles are stored before any cell owns them,
//    so BoundaryFaceNotOnCell and OpenBoundary are expected; every cell-level violation
//    (volume, degenerate cell, face on three cells, orientation, quad against triangles)
//    still fails.
//  * after pyramids, in addition: the tet front (PipelineResult::tet_front) must be closed
//    and consistently oriented — every edge on exactly two front triangles, once in each
//    direction — since the tet step fills exactly the region it bounds.
#include <string>
#include <vector>

#include "engine/check/mesh_check.hpp"
#include "engine/pipeline/pipeline.hpp"

namespace tubemesh {

// True when a mesh that stopped after `reached` may have this violation.
bool violation_expected(ViolationKind kind, Stage reached);

// Front edges that are not shared by exactly two triangles in opposite directions: 0 for a
// closed, consistently oriented triangle surface (3 node ids per triangle).
std::size_t front_defects(const std::vector<index_t>& triangles);

// Runs the check on result.mesh (and the front after pyramids), stores the report in
// result.check, appends a "check" phase to result.phases and its time to result.seconds.
// Throws tubemesh::Error, one line naming every failing kind with its count and first
// elements, when the mesh fails; the result is then not fit to be written.
void check_result(PipelineResult& result, const ProgressCallback& progress = {});

}  // namespace tubemesh
