#include "engine/surface/mesh_surfaces.hpp"

#include <algorithm>
#include <exception>
#include <numeric>
#include <string>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace tubemesh::surface {

SurfaceMeshStats mesh_surfaces(std::span<const SurfaceFace> faces, const SizeField& size,
                               const FaceMeshOptions& options, HybridMesh& mesh) {
    for (const SurfaceFace& f : faces) {
        if (f.surface == nullptr) throw Error("surface meshing: a face has no surface map");
        for (index_t id : f.boundary.node_id)
            if (id >= mesh.point_count())
                throw Error("surface meshing: face_" + std::to_string(f.surface->face()) + " refers to node " +
                            std::to_string(id) + " but the mesh has " + std::to_string(mesh.point_count()) +
                            " points");
    }
    std::vector<FaceMesh> results(faces.size());
    // Errors are kept per face and the first one in face order is rethrown, so which message a
    // user sees does not depend on which thread failed first.
    std::vector<std::exception_ptr> errors(faces.size());
    // Faces with the longest boundaries (a rough measure of their work) are handed out first, so
    // one big face started last does not leave the other threads idle. Results go by face
    // index, so the order only affects timing.
    std::vector<std::size_t> order(faces.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return faces[a].boundary.loop_node.size() > faces[b].boundary.loop_node.size();
    });
    tbb::enumerable_thread_specific<FaceMesher> meshers;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces.size(), 1), [&](const auto& range) {
        FaceMesher& mesher = meshers.local();
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const std::size_t i = order[k];
            const SurfaceMap& surface = *faces[i].surface;
            try {
                mesher.mesh(surface, faces[i].boundary, size, options, results[i]);
            } catch (const Error& e) {
                // Errors from the surface map itself do not know which face they came from.
                const std::string label = "face_" + std::to_string(surface.face());
                const std::string what = e.what();
                errors[i] = std::make_exception_ptr(what.rfind(label, 0) == 0 ? e : Error(label + ": " + what));
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    });
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);

    SurfaceMeshStats stats;
    stats.faces = static_cast<index_t>(faces.size());
    std::vector<index_t> global;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const FaceMesh& r = results[i];
        const FaceBoundary& b = faces[i].boundary;
        global.assign(b.node_id.begin(), b.node_id.end());
        for (index_t k = r.boundary_count; k < r.xyz.size(); ++k)
            global.push_back(mesh.add_point(r.xyz[k].x, r.xyz[k].y, r.xyz[k].z));
        for (index_t t = 0; t < r.triangle_count(); ++t) {
            const index_t tri[3] = {global[r.triangles[3 * t]], global[r.triangles[3 * t + 1]],
                                    global[r.triangles[3 * t + 2]]};
            mesh.add_face(FaceKind::Tri, tri, faces[i].group);
        }
        stats.triangles += r.triangle_count();
        stats.interior_nodes += static_cast<index_t>(r.xyz.size()) - r.boundary_count;
        stats.totals.points_inserted += r.stats.points_inserted;
        stats.totals.points_refused += r.stats.points_refused;
        stats.totals.flips += r.stats.flips;
        stats.totals.moves += r.stats.moves;
        stats.totals.collapses += r.stats.collapses;
    }
    return stats;
}

}  // namespace tubemesh::surface
