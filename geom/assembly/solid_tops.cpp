#include "geom/assembly/solid_tops.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "geom/model/face_names.hpp"

namespace tubemesh::geom {

void describe_solid_tops(const Assembly& assembly, const HybridMesh& mesh, MeshDescription& description) {
    const std::vector<AssemblySolid>& solids = assembly.solids();
    // Per pair of solids, the faces they share.
    std::map<std::pair<int, int>, std::set<int>> joints;
    std::map<int, std::pair<int, int>> joint_of_face;
    for (const SharedFace& f : assembly.shared_faces()) {
        joints[{f.first, f.second}].insert(f.face);
        joint_of_face[f.face] = {f.first, f.second};
    }
    auto group_id = [&](const std::string& name) -> std::optional<index_t> {
        const auto it = std::find(mesh.surface_group_names.begin(), mesh.surface_group_names.end(), name);
        if (it == mesh.surface_group_names.end()) return std::nullopt;
        return static_cast<index_t>(it - mesh.surface_group_names.begin());
    };
    for (std::size_t k = 0; k < solids.size(); ++k) {
        const AssemblySolid& s = solids[k];
        const std::vector<std::string> sides = box_sides(s.model);
        std::set<int> tops;
        for (std::size_t i = 0; i < sides.size(); ++i)
            if (sides[i] == "top") tops.insert(s.face_ids[i]);
        std::set<index_t> groups;
        bool whole = !tops.empty();
        for (int face : tops) {
            std::optional<index_t> g;
            if (const auto joint = joint_of_face.find(face); joint != joint_of_face.end()) {
                const auto [a, b] = joint->second;
                const std::set<int>& shared = joints[joint->second];
                if (std::includes(tops.begin(), tops.end(), shared.begin(), shared.end()))
                    g = group_id("joint_" + solids[static_cast<std::size_t>(a)].name + "_" +
                                 solids[static_cast<std::size_t>(b)].name);
            } else {
                g = group_id(Model::face_name(face));
            }
            if (g) groups.insert(*g);
            whole = whole && g.has_value();
        }
        // A top that is only partly a group of its own would name faces that are not the top.
        if (!whole || groups.empty()) continue;
        description.region_surfaces.push_back(
            {s.name + "_top", static_cast<index_t>(k), std::vector<index_t>(groups.begin(), groups.end())});
    }
}

}  // namespace tubemesh::geom
