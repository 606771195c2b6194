// MshContents -> HybridMesh: physical groups become regions (dimension 3) and surface groups
// (dimension 2); element tags restore the mesh order of each kind.
//
// Group ids: the physical tags of that dimension - named in $PhysicalNames or carried by an
// entity that holds elements - in ascending order, so tubemesh's own tags 1..n give ids
// 0..n-1 back. Unnamed physical groups are called "volume_<tag>" / "surface_<tag>". Elements
// on an entity without a physical tag (Gmsh files saved with Mesh.SaveAll) get one group per
// such entity after those, called "volume_entity_<tag>" / "surface_entity_<tag>".
#include <algorithm>
#include <map>

#include "engine/io/msh_contents.hpp"

namespace tubemesh::io {

namespace {

struct GroupTable {
    std::vector<std::string> names;
    std::vector<index_t> of_block;  // group id per element block (kNoIndex: other dimension)
};

GroupTable group_table(const MshContents& c, int dimension, const char* prefix) {
    std::map<int, std::optional<int>> physical_of_entity;
    for (const MshEntity& e : c.entities)
        if (e.dimension == dimension) physical_of_entity.try_emplace(e.tag, e.physical);
    auto physical_of = [&](int entity) {
        const auto it = physical_of_entity.find(entity);
        return it == physical_of_entity.end() ? std::optional<int>{} : it->second;
    };

    std::map<int, std::string> physical_names;  // ascending tag; first name given wins
    for (const MshPhysicalName& p : c.physical_names)
        if (p.dimension == dimension) physical_names.try_emplace(p.tag, p.name);
    std::map<int, index_t> entity_groups;  // entities without a physical tag
    for (const MshElementBlock& b : c.blocks) {
        if (b.dimension != dimension) continue;
        if (const auto p = physical_of(b.entity))
            physical_names.try_emplace(*p, std::string(prefix) + "_" + std::to_string(*p));
        else
            entity_groups.try_emplace(b.entity, kNoIndex);
    }

    GroupTable t;
    std::map<int, index_t> id_of_physical;
    for (const auto& [tag, name] : physical_names) {
        id_of_physical[tag] = static_cast<index_t>(t.names.size());
        t.names.push_back(name);
    }
    for (auto& [entity, id] : entity_groups) {
        id = static_cast<index_t>(t.names.size());
        t.names.push_back(std::string(prefix) + "_entity_" + std::to_string(entity));
    }
    t.of_block.reserve(c.blocks.size());
    for (const MshElementBlock& b : c.blocks) {
        if (b.dimension != dimension) {
            t.of_block.push_back(kNoIndex);
            continue;
        }
        const auto p = physical_of(b.entity);
        t.of_block.push_back(p ? id_of_physical.at(*p) : entity_groups.at(b.entity));
    }
    return t;
}

// Appends the elements in ascending tag order, which is the mesh order for tubemesh's files.
void place_elements(const MshElements& e, std::size_t node_count, const std::vector<index_t>& group_of_block,
                    std::vector<index_t>& nodes, std::vector<index_t>& groups) {
    nodes.reserve(e.nodes.size());
    groups.reserve(e.order.size());
    for (index_t k : e.order) {
        const auto first = e.nodes.begin() + static_cast<std::ptrdiff_t>(std::size_t{k} * node_count);
        nodes.insert(nodes.end(), first, first + static_cast<std::ptrdiff_t>(node_count));
        groups.push_back(group_of_block[e.block[k]]);
    }
}

}  // namespace

HybridMesh assemble_msh(MshContents&& c) {
    HybridMesh m;
    m.x = std::move(c.x);
    m.y = std::move(c.y);
    m.z = std::move(c.z);
    GroupTable regions = group_table(c, 3, "volume");
    GroupTable surfaces = group_table(c, 2, "surface");
    for (CellKind k : kAllCellKinds)
        place_elements(c.elements[msh_kind_index(k)], static_cast<std::size_t>(node_count(k)), regions.of_block,
                       m.block(k).nodes, m.block(k).region);
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
        place_elements(c.elements[msh_kind_index(k)], static_cast<std::size_t>(face_size(k)), surfaces.of_block,
                       m.block(k).nodes, m.block(k).group);
    m.region_names = std::move(regions.names);
    m.surface_group_names = std::move(surfaces.names);
    m.validate_layout();  // holds by construction; cheap insurance against a parser slip
    return m;
}

}  // namespace tubemesh::io
