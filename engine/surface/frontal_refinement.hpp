#pragma once
// Second step of meshing a face: frontal Delaunay refinement of the boundary triangulation
// (Rebay, J. Comput. Phys. 106, 1993). Internal to engine/surface.
//
// Each inside triangle is "accepted" once its circumradius is at most accept_ratio times that
// of the ideal (equilateral) triangle of the local size, measured both in space and in the
// mean metric of its corners (the larger wins: chords in space miss a triangle spanning a
// seam or much of a curved face), and it does not fold over in space. The front is the set of
// unaccepted triangles next to an accepted one or to the boundary; the one with the largest
// circumradius ratio goes first. On its front edge the new point is put where it forms the
// ideal triangle with that edge, measured in the surface metric at the edge's midpoint, but no
// farther than the triangle's circumcentre, so that the triangle is in the new point's cavity.
#include <vector>

#include "engine/surface/face_mesher.hpp"
#include "engine/surface/uv_insertion.hpp"
#include "engine/surface/uv_mesh.hpp"

namespace tubemesh::surface {

class FrontalRefiner {
public:
    // New vertices get provisional output nodes first_node, first_node + 1, ... in insertion
    // order (the mesher renumbers them after the optimisation removes some).
    void run(const SurfaceMap& surface, const SizeField& size, const FaceMeshOptions& options, index_t first_node,
             UvMesh& mesh, Inserter& inserter, FaceMeshStats& stats);

private:
    struct Entry {
        double ratio;
        index_t triangle;
        std::uint32_t gen;
    };
    double radius_ratio(const UvMesh& mesh, index_t t) const;
    int front_edge(const UvMesh& mesh, index_t t) const;
    void push_if_front(const UvMesh& mesh, index_t t);
    void settle(UvMesh& mesh, index_t t, double accept_ratio);
    void accept(UvMesh& mesh, index_t t);
    bool place_point(const SurfaceMap& surface, const UvMesh& mesh, index_t t, int edge, Uv& p) const;

    std::vector<double> ratio_;  // per triangle slot
    std::vector<Entry> heap_;
};

}  // namespace tubemesh::surface
