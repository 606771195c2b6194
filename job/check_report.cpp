#include "job/check_report.hpp"

#include "job/quality_table.hpp"

namespace tubemesh::job {

namespace {

const char* set_name(ElementRef::Set s) {
    switch (s) {
        case ElementRef::Set::Tet: return "tet";
        case ElementRef::Set::Pyramid: return "pyramid";
        case ElementRef::Set::Hex: return "hex";
        case ElementRef::Set::BoundaryTri: return "boundary triangle";
        case ElementRef::Set::BoundaryQuad: return "boundary quad";
    }
    return "?";
}

}  // namespace

nlohmann::json check_json(const HybridMesh& mesh, const CheckReport& report, const QualitySummary& q) {
    nlohmann::json violations = nlohmann::json::array();
    for (const Violation& v : report.violations) {
        nlohmann::json first = nlohmann::json::array();
        for (const ElementRef& r : v.first) first.push_back({{"set", set_name(r.set)}, {"index", r.index}});
        violations.push_back({{"kind", violation_name(v.kind)}, {"count", v.count}, {"first", first}});
    }
    return {{"nodes", mesh.point_count()},
            {"tets", mesh.cell_count(CellKind::Tet)},
            {"pyramids", mesh.cell_count(CellKind::Pyramid)},
            {"hexes", mesh.cell_count(CellKind::Hex)},
            {"boundary_triangles", mesh.face_count(FaceKind::Tri)},
            {"boundary_quads", mesh.face_count(FaceKind::Quad)},
            {"valid_and_conforming", report.ok()},
            {"violations", violations},
            {"interior_faces", report.interior_faces},
            {"free_faces", report.boundary_faces},
            {"volume", report.volume},
            {"boundary_area", report.boundary_area},
            {"regions", mesh.region_names},
            {"surface_groups", mesh.surface_group_names},
            {"quality", quality_json(q)}};
}

}  // namespace tubemesh::job
