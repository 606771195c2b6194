#include "engine/io/mesh_notes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/mesh/surface_groups.hpp"

namespace tubemesh::io {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v == 0 ? 0.0 : v);  // no "-0"
    return text;
}

// A component 1e-12 of the largest or less is rounding (a normal's 8.7e-51, a centroid's 4e-34 on
// a plane through 0): printed as 0.
std::string triple(const Vec3& v) {
    const double scale = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    const auto clean = [&](double c) { return std::abs(c) <= 1e-12 * scale ? 0.0 : c; };
    std::string s = "(";
    s += number(clean(v.x)) + ", " + number(clean(v.y)) + ", " + number(clean(v.z)) + ")";
    return s;
}

std::string padded(std::string s, std::size_t width) {
    if (s.size() < width) s.resize(width, ' ');
    return s;
}

}  // namespace

std::string group_role(const HybridMesh& mesh, const MeshDescription* description, std::size_t group) {
    if (description && description->group(group) && !description->group(group)->alias.empty())
        return description->group(group)->alias;
    return mesh.surface_group_names[group].rfind("pipe_", 0) == 0 ? "pipe wall" : "";
}

std::vector<std::string> mesh_notes(const HybridMesh& mesh, const MeshDescription* description) {
    std::vector<std::string> lines;
    const std::string unit = description && !description->length_unit.empty() ? description->length_unit : "not known";
    lines.push_back("length unit: " + unit + " (coordinates as in the model)");
    const std::vector<SurfaceGroupGeometry> geometry = surface_group_geometry(mesh);
    if (!geometry.empty())
        lines.push_back("surface groups: name, where, CAD surface, faces, area, centroid, outward normal if flat");
    std::size_t width = 0;
    for (const std::string& name : mesh.surface_group_names) width = std::max(width, name.size());
    for (std::size_t g = 0; g < geometry.size(); ++g) {
        const SurfaceGroupGeometry& s = geometry[g];
        const SurfaceGroupInfo* info = description ? description->group(g) : nullptr;
        std::string line = "  " + padded(mesh.surface_group_names[g], width) + "  " +
                           padded(group_role(mesh, description, g), 10) + "  " +
                           padded(info && !info->surface_kind.empty() ? info->surface_kind : "-", 9) + "  " +
                           std::to_string(s.faces) + " faces, area " + number(s.area) + ", centroid " +
                           triple(s.centroid);
        if (s.flat) line += ", normal " + triple(s.normal);
        lines.push_back(line);
    }
    if (description && !description->region_surfaces.empty()) {
        lines.push_back("region surfaces: name, region (its element set), surface groups (the faces of the region's "
                        "elements on them)");
        for (const RegionSurface& r : description->region_surfaces) {
            std::string line = "  " + r.name + "  " + mesh.region_names[r.region] + " ";
            for (index_t g : r.groups) line += " " + mesh.surface_group_names[g];
            lines.push_back(line);
        }
    }
    if (description && !description->node_sets.empty()) {
        std::string sets = "node sets:";
        for (const NamedNodeSet& n : description->node_sets)
            sets += " " + n.name + " (" + std::to_string(n.nodes.size()) + ")";
        lines.push_back(sets);
        lines.push_back("  pipe_<k>_inlet / _outlet: the wall nodes at the pipe's first / second end (inspect's host1 / host2)");
        for (const NamedNodeSet& n : description->node_sets)
            if (n.name.ends_with("_ring_stop")) {
                lines.push_back("  pipe_<k>_ring_stop: the wall nodes where a pipe's hex ring stops inside the solid (its wall goes on with tetrahedra)");
                break;
            }
    }
    return lines;
}

}  // namespace tubemesh::io
