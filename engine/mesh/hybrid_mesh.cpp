#include "engine/mesh/hybrid_mesh.hpp"

#include <algorithm>
#include <string>

namespace tubemesh {

namespace {

index_t find_or_add(std::vector<std::string>& names, const std::string& name) {
    auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return static_cast<index_t>(it - names.begin());
    names.push_back(name);
    return static_cast<index_t>(names.size() - 1);
}

void check_block(const std::vector<index_t>& nodes, const std::vector<index_t>& ids, std::size_t stride,
                 index_t point_count, std::size_t name_count, const char* what) {
    if (nodes.size() != ids.size() * stride)
        throw Error(std::string("mesh layout: ") + what + " has " + std::to_string(nodes.size()) +
                    " node entries for " + std::to_string(ids.size()) + " elements");
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i] >= point_count)
            throw Error(std::string("mesh layout: ") + what + " " + std::to_string(i / stride) +
                        " refers to node " + std::to_string(nodes[i]) + " of " + std::to_string(point_count));
    for (std::size_t i = 0; i < ids.size(); ++i)
        if (ids[i] >= name_count)
            throw Error(std::string("mesh layout: ") + what + " " + std::to_string(i) + " has group id " +
                        std::to_string(ids[i]) + " but only " + std::to_string(name_count) + " names exist");
}

}  // namespace

index_t HybridMesh::add_point(double px, double py, double pz) {
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
    return static_cast<index_t>(x.size() - 1);
}

index_t HybridMesh::cell_count(CellKind k) const { return static_cast<index_t>(block(k).region.size()); }

index_t HybridMesh::cell_count() const {
    index_t n = 0;
    for (CellKind k : kAllCellKinds) n += cell_count(k);
    return n;
}

index_t HybridMesh::face_count(FaceKind k) const { return static_cast<index_t>(block(k).group.size()); }

std::span<const index_t> HybridMesh::cell(CellKind k, index_t i) const {
    const std::size_t n = static_cast<std::size_t>(node_count(k));
    return {block(k).nodes.data() + n * i, n};
}

std::span<const index_t> HybridMesh::face(FaceKind k, index_t i) const {
    const std::size_t n = static_cast<std::size_t>(face_size(k));
    return {block(k).nodes.data() + n * i, n};
}

index_t HybridMesh::add_cell(CellKind k, std::span<const index_t> nodes, index_t region) {
    if (nodes.size() != static_cast<std::size_t>(node_count(k)))
        throw Error(std::string("add_cell: a ") + topology(k).name + " needs " + std::to_string(node_count(k)) +
                    " nodes, got " + std::to_string(nodes.size()));
    CellBlock& b = block(k);
    b.nodes.insert(b.nodes.end(), nodes.begin(), nodes.end());
    b.region.push_back(region);
    return static_cast<index_t>(b.region.size() - 1);
}

index_t HybridMesh::add_face(FaceKind k, std::span<const index_t> nodes, index_t group) {
    if (nodes.size() != static_cast<std::size_t>(face_size(k)))
        throw Error("add_face: a boundary face of this kind needs " + std::to_string(face_size(k)) + " nodes, got " +
                    std::to_string(nodes.size()));
    FaceBlock& b = block(k);
    b.nodes.insert(b.nodes.end(), nodes.begin(), nodes.end());
    b.group.push_back(group);
    return static_cast<index_t>(b.group.size() - 1);
}

index_t HybridMesh::region_id(const std::string& name) { return find_or_add(region_names, name); }

index_t HybridMesh::surface_group_id(const std::string& name) { return find_or_add(surface_group_names, name); }

void HybridMesh::validate_layout() const {
    if (y.size() != x.size() || z.size() != x.size())
        throw Error("mesh layout: coordinate arrays differ in length (x " + std::to_string(x.size()) + ", y " +
                    std::to_string(y.size()) + ", z " + std::to_string(z.size()) + ")");
    for (CellKind k : kAllCellKinds)
        check_block(block(k).nodes, block(k).region, static_cast<std::size_t>(node_count(k)), point_count(),
                    region_names.size(), topology(k).name);
    check_block(block(FaceKind::Tri).nodes, block(FaceKind::Tri).group, 3, point_count(),
                surface_group_names.size(), "boundary triangle");
    check_block(block(FaceKind::Quad).nodes, block(FaceKind::Quad).group, 4, point_count(),
                surface_group_names.size(), "boundary quad");
}

void HybridMesh::clear() { *this = HybridMesh{}; }

}  // namespace tubemesh
