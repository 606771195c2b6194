#include "engine/surface/face_mesher.hpp"

#include <string>

#include "engine/surface/boundary_triangulation.hpp"
#include "engine/surface/frontal_refinement.hpp"
#include "engine/surface/surface_optimisation.hpp"
#include "engine/surface/uv_insertion.hpp"
#include "engine/surface/uv_mesh.hpp"

namespace tubemesh::surface {

index_t FaceBoundary::add_node(index_t id, const Vec3& p) {
    node_id.push_back(id);
    xyz.push_back(p);
    return static_cast<index_t>(node_id.size() - 1);
}

void FaceBoundary::add_loop_point(index_t node, Uv uv) {
    loop_node.push_back(node);
    loop_uv.push_back(uv);
}

void FaceBoundary::close_loop() { loop_begin.push_back(static_cast<index_t>(loop_node.size())); }

// Everything a mesher keeps between faces.
class FaceMesherState {
public:
    UvMesh mesh;
    Inserter inserter;
    BoundaryScratch boundary;
    FrontalRefiner refiner;
    SurfaceOptimiser optimiser;
};

FaceMesher::FaceMesher() : state_(std::make_unique<FaceMesherState>()) {}
FaceMesher::~FaceMesher() = default;
FaceMesher::FaceMesher(FaceMesher&&) noexcept = default;
FaceMesher& FaceMesher::operator=(FaceMesher&&) noexcept = default;

namespace {

void check_boundary(const SurfaceMap& surface, const FaceBoundary& b) {
    const std::string face = "face_" + std::to_string(surface.face());
    if (b.xyz.size() != b.node_id.size())
        throw Error(face + ": boundary has " + std::to_string(b.node_id.size()) + " node ids but " +
                    std::to_string(b.xyz.size()) + " positions");
    if (b.loop_uv.size() != b.loop_node.size() || b.loop_begin.empty() || b.loop_begin.front() != 0 ||
        b.loop_begin.back() != b.loop_node.size())
        throw Error(face + ": boundary loops are not closed (call close_loop() after each loop)");
    if (b.loop_count() == 0) throw Error(face + ": no boundary loop given");
    for (index_t l = 0; l < b.loop_count(); ++l)
        if (b.loop_begin[l + 1] - b.loop_begin[l] < 3)
            throw Error(face + ": boundary loop " + std::to_string(l) + " has fewer than 3 points");
    for (index_t n : b.loop_node)
        if (n >= b.node_id.size())
            throw Error(face + ": a loop refers to boundary node " + std::to_string(n) + " of " +
                        std::to_string(b.node_id.size()));
}

void check_options(const FaceMeshOptions& o) {
    // Below 1 no triangle could ever be accepted; spacing 1 or more would refuse ideal points.
    if (!(o.accept_ratio >= 1.0 && o.accept_ratio < 10.0))
        throw Error("surface meshing: accept_ratio must be in [1, 10), got " + std::to_string(o.accept_ratio));
    if (!(o.min_spacing >= 0.0 && o.min_spacing < 1.0))
        throw Error("surface meshing: min_spacing must be in [0, 1), got " + std::to_string(o.min_spacing));
    if (o.optimisation_passes < 0)
        throw Error("surface meshing: optimisation_passes must not be negative, got " +
                    std::to_string(o.optimisation_passes));
}

}  // namespace

void FaceMesher::mesh(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
                      const FaceMeshOptions& options, FaceMesh& out) {
    check_options(options);
    check_boundary(surface, boundary);
    FaceMesherState& s = *state_;
    out.stats = {};
    triangulate_boundary(surface, boundary, size, s.mesh, s.inserter, s.boundary);
    const index_t first_interior = s.mesh.vertex_count();
    s.refiner.run(surface, size, options, boundary.node_count(), s.mesh, s.inserter, out.stats);
    s.optimiser.run(surface, options.optimisation_passes, first_interior, s.mesh, out.stats);

    // Output numbering: boundary nodes as given, then the interior vertices that survived the
    // optimisation, in creation order.
    UvMesh& m = s.mesh;
    out.boundary_count = boundary.node_count();
    out.xyz.assign(boundary.xyz.begin(), boundary.xyz.end());
    out.interior_uv.clear();
    for (index_t v = first_interior; v < m.vertex_count(); ++v) {
        if (m.removed(v)) continue;
        m.node[v] = static_cast<index_t>(out.xyz.size());
        out.xyz.push_back(m.xyz[v]);
        out.interior_uv.push_back(m.uv[v]);
    }
    // Counter-clockwise in uv is a right-hand normal along du x dv.
    const bool flip = surface.reversed();
    out.triangles.clear();
    for (index_t t = 0; t < m.slot_count(); ++t) {
        if (m.dead(t) || !m.inside(t)) continue;
        const index_t a = m.node[m.vertex(t, 0)], b = m.node[m.vertex(t, 1)], c = m.node[m.vertex(t, 2)];
        if (a == b || b == c || c == a) continue;  // collapsed onto a pole
        out.triangles.push_back(a);
        out.triangles.push_back(flip ? c : b);
        out.triangles.push_back(flip ? b : c);
    }
}

FaceMesh mesh_face(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
                   const FaceMeshOptions& options) {
    FaceMesher mesher;
    FaceMesh out;
    mesher.mesh(surface, boundary, size, options, out);
    return out;
}

}  // namespace tubemesh::surface
