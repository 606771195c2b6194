#pragma once
// The acceptance figures of the hex rings, the surface and the pyramid layer, measured
// on one block run through the real pipeline (geom builders -> prepare -> run_pipeline), each
// independently of the modules' own statistics: element quality from the mesh, node positions
// by projection onto geom's SurfaceMaps, areas against OpenCASCADE's, closed surfaces with the
// exact predicates (tests/support/surface_test_support.hpp's inspect_closed).
#include <string>
#include <vector>

#include "engine/check/mesh_check.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "geom/builders/block_spec.hpp"
#include "geom/prepare.hpp"
#include "tests/support/surface_test_support.hpp"

namespace tubemesh::acceptance {

// A closed-surface report plus what inspect_closed does not count.
struct SurfaceFigures {
    testing::ClosedReport closed;
    index_t components = 0;  // connected pieces (by shared nodes)
    index_t tubes = 0;       // holes through the solid: one closed surface has Euler 2 - 2·tubes
};

struct RingAcceptance {
    index_t hexes = 0;
    double min_jacobian = 0, mean_jacobian = 0, max_condition = 0;
    double wall_error = 0;  // largest distance of a wall node from its tube's wall faces, over r
    double wall_error_inner_stations = 0;  // the same without the end stations (the rings' loops)
    double host_error = 0;  // largest distance of an end node from its host face, over r
    CheckReport ring_check; // the sweep-only mesh with its outer quads as boundary faces
};

struct SurfaceAcceptance {
    index_t triangles = 0;
    SurfaceFigures surface;       // end quads + triangles (+ the wall quads that close the holes)
    double node_error = 0;        // largest distance of a triangle node from its face, over h(x)
    double min_angle = 0;         // degrees
    double fraction_above_40 = 0; // of triangles with all angles >= 40 degrees
    // Area of each face's triangles and end quads against the B-rep face's area.
    double flat_area_error = 0;   // largest relative error over flat faces
    index_t curved_faces = 0;
    index_t curved_over_chord = 0;  // curved faces whose area error exceeds the chord bound
    double curved_area_error = 0;   // largest relative error over curved faces (for the report)
    std::string area_problems;      // one line per face out of bounds
    // Neighbouring triangles (sharing an edge, within a face or across a B-rep edge): ratio of
    // their mean edge lengths.
    double max_neighbor_ratio = 0;
    index_t pairs = 0, pairs_above_1_5 = 0;
    std::string worst_pair;  // where the largest ratio is, for the report
};

struct PyramidAcceptance {
    index_t outer_quads = 0, pyramids = 0;
    index_t quads_without_one_pyramid = 0;  // outer quads not the base of exactly one pyramid
    SurfaceFigures front;                   // PipelineResult::tet_front alone
    double min_jacobian = 0, mean_jacobian = 0;
    PyramidStats stats;
};

struct CaseFigures {
    std::string name;
    index_t tubes = 0;
    double size = 0, sweep_size = 0;  // S and St the plan chose
    double seconds = 0;               // pipeline run to the pyramids, for the report
    RingAcceptance rings;
    SurfaceAcceptance surface;
    PyramidAcceptance pyramids;
};

// Builds the block, prepares it with `options`, runs the pipeline to the sweep (for the ring
// check) and to the pyramids, and measures everything above. Throws tubemesh::Error when a
// step fails.
CaseFigures measure_case(const std::string& name, const geom::BlockSpec& spec,
                         const geom::PrepareOptions& options = {}, const MeshOptions& mesh_options = {});

// One line per figure, for the test log.
std::string summary(const CaseFigures& f);

// The bars of each step as gtest expectations (each failure names the case and figure).
// (All hold on every preset and seeds 1-50; the gaps executable keeps only pipes closer than
// the sizing guards allow.)
void expect_rings_accepted(const CaseFigures& f);     // J_m >= 0.5, Cond <= 4, mean >= 0.70, hosts 1e-7 r, check
void expect_surface_accepted(const CaseFigures& f);   // closed surface, nodes on faces, curved areas
void expect_wall_nodes_accepted(const CaseFigures& f);      // wall nodes within 1e-7 r of the wall
void expect_triangle_angles_accepted(const CaseFigures& f); // min angle >= 20, 95 % >= 40
void expect_flat_area_accepted(const CaseFigures& f);       // flat faces' area within 1e-3
void expect_neighbor_ratio_accepted(const CaseFigures& f);  // neighbouring triangles within 1.5
void expect_pyramid_layer_accepted(const CaseFigures& f);   // one per quad, closed front
void expect_pyramid_quality_accepted(const CaseFigures& f); // min >= 0.45, mean >= 0.80

}  // namespace tubemesh::acceptance
