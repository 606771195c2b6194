#pragma once
// The acceptance figures of the tet step (paper §5) on one block run through the real
// pipeline (geom builders -> prepare -> run_pipeline to Stage::Tets), measured from the mesh
// alone, independently of the tet step's own statistics: how each front triangle is covered,
// exact orientation of every tet, volume against the front's, check_mesh, tet collapse.
#include <string>

#include "engine/check/mesh_check.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/builders/block_spec.hpp"

namespace tubemesh::tets_acceptance {

struct TetFigures {
    std::string name;
    index_t front_triangles = 0, tets = 0, new_points = 0;
    // Front triangles that are not a face of exactly one tet, and those whose one tet lies on
    // the outer side (the front's normal points out of the region).
    index_t front_not_one_tet = 0, front_wrong_side = 0;
    // Tet faces that are no front triangle yet lie on one tet only, or lie on more than two:
    // the tets do not fill exactly the region the front bounds.
    index_t loose_faces = 0, crowded_faces = 0;
    index_t not_positive = 0;  // tets with exact orient3d <= 0
    double tet_volume = 0, enclosed_volume = 0;
    CheckReport check;  // the whole hybrid mesh
    double min_collapse = 0, mean_collapse = 0;
    index_t below_0_2 = 0, below_0_3 = 0;
    // The worst tet: how many of its nodes and faces are on the front (4 and 2: it spans a
    // wedge of the front, and no tet step can do better there).
    int worst_front_nodes = 0, worst_front_faces = 0;
    tets::TetStepStats stats;
    double pipeline_seconds = 0;  // the whole run, for the report
    std::string first_problems;   // a few offending elements, for the failure message
};

// Builds the block, prepares it with the sizes of `options` (S, St, n; 0 = geom's defaults)
// and runs the pipeline with `options`. Throws tubemesh::Error when a step fails.
TetFigures measure_tets(const std::string& name, const geom::BlockSpec& spec, const MeshOptions& options = {});

// The same measures on a mesh the caller ran (tet_front from the same run).
TetFigures measure_tets(const std::string& name, const PipelineResult& result);

// One line per block, for the test log.
std::string summary(const TetFigures& f);

// The tet step's bars as gtest expectations, each failure naming the block.
// Every front triangle a face of one tet on its inner side, tets positive, volume to 1e-9
// relative, check_mesh clean.
void expect_tets_fill_the_front(const TetFigures& f);
// Tet collapse min >= 0.30 and none below 0.20.
void expect_tet_minimum(const TetFigures& f);
// Tet collapse mean >= 0.80.
void expect_tet_mean(const TetFigures& f);

}  // namespace tubemesh::tets_acceptance
