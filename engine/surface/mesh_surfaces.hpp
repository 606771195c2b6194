#pragma once
// Surface triangles of every face that is not a tube wall, faces meshed in parallel (oneTBB)
// and merged into the mesh store in a fixed order, so the result does not depend on the
// thread count or on timing.
#include <span>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/surface/face_mesher.hpp"

namespace tubemesh::surface {

struct SurfaceFace {
    const SurfaceMap* surface = nullptr;
    // node_id are HybridMesh point ids: the shared edge discretisation's nodes and the rings'
    // outer polygon nodes, already in the mesh.
    FaceBoundary boundary;
    index_t group = 0;  // HybridMesh surface group id of the face's triangles
};

struct SurfaceMeshStats {
    index_t faces = 0;
    index_t triangles = 0;
    index_t interior_nodes = 0;
    FaceMeshStats totals;  // summed over faces
};

// Meshes faces[i] for every i and appends, face after face, its interior nodes (in the face's
// creation order) to the mesh's points and its triangles to the triangle block with the face's
// group. Throws tubemesh::Error naming the first face (in face order) that failed.
SurfaceMeshStats mesh_surfaces(std::span<const SurfaceFace> faces, const SizeField& size,
                               const FaceMeshOptions& options, HybridMesh& mesh);

}  // namespace tubemesh::surface
