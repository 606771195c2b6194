#pragma once
// Last step of meshing a face: edge flips, vertex smoothing and edge collapses judged by angles
// in space. Frontal refinement leaves a few poor triangles where fronts meet; flipping to the
// better diagonal, moving interior vertices (on the surface) and removing a vertex that crowds
// a bad triangle fix most of them. Each change must improve the worst angle it touches, and
// only triangles with an angle under 50 degrees are looked at, so a pass costs little more
// than a scan of the cached triangle qualities. A last sweep evens out sizes where two
// neighbouring triangles differ by more than 1.4 (mean edge length), moving the apex of one of
// them while no angle it touches drops below 30 degrees. Boundary vertices and edges never
// change.
// Internal to engine/surface.
#include <vector>

#include "engine/surface/face_mesher.hpp"
#include "engine/surface/uv_mesh.hpp"

namespace tubemesh::surface {

class SurfaceOptimiser {
public:
    // Vertices from first_movable on may move (the interior ones).
    void run(const SurfaceMap& surface, int passes, index_t first_movable, UvMesh& mesh, FaceMeshStats& stats);

private:
    index_t flip_sweep(UvMesh& mesh);
    index_t smooth_sweep(const SurfaceMap& surface, index_t first_movable, UvMesh& mesh);
    index_t collapse_sweep(index_t first_movable, UvMesh& mesh);
    bool try_flip(UvMesh& mesh, index_t t, int i);
    bool try_smooth(const SurfaceMap& surface, UvMesh& mesh, index_t v);
    bool try_collapse(index_t v, index_t w, UvMesh& mesh);
    index_t grading_sweep(const SurfaceMap& surface, index_t first_movable, UvMesh& mesh);
    bool try_grade(const SurfaceMap& surface, UvMesh& mesh, index_t v, index_t a, index_t b);
    struct StarRatio {
        double worst = 1;    // the largest size ratio of two neighbouring triangles
        double penalty = 0;  // sum of log(ratio / 1.4)^2 over the ratios above 1.4
    };
    StarRatio star_ratio(const UvMesh& mesh, index_t v, const Vec3& at) const;  // over the gathered fan
    bool gather_ring(const UvMesh& mesh, index_t v);
    double fan_worst() const;  // over the fan gathered last, from the cache
    double fan_cosine(const UvMesh& mesh, const Vec3& at, std::size_t j) const;  // of (at, ring j, ring j+1)
    bool fan_faces_out(const UvMesh& mesh, index_t v, const Vec3& at) const;    // with v moved to at
    void update_quality(const UvMesh& mesh, index_t t);

    std::vector<double> quality_;  // per triangle slot: the largest cosine of its angles
    std::vector<double> size_;     // per triangle slot: its mean edge length
    std::vector<index_t> ring_;    // neighbours of the vertex at hand, counter-clockwise
    std::vector<index_t> fan_;     // fan_[j] = triangle (v, ring_[j], ring_[j+1])
    std::vector<index_t> work_;    // vertices to smooth in this sweep, ascending
    std::vector<std::uint32_t> vertex_mark_;
    std::uint32_t vertex_epoch_ = 0;
};

}  // namespace tubemesh::surface
