#include "engine/io/boundary_cell_faces.hpp"

#include <algorithm>

namespace tubemesh::io {

namespace {

// A face's nodes sorted ascending, padded with kNoIndex: equal for equal node sets.
using FaceKey = std::array<index_t, 4>;

template <class Nodes>
FaceKey make_key(const Nodes& nodes, int size) {
    FaceKey k{kNoIndex, kNoIndex, kNoIndex, kNoIndex};
    // Insertion sort: at most four entries.
    for (int i = 0; i < size; ++i) {
        index_t v = nodes[i];
        int j = i;
        for (; j > 0 && k[j - 1] > v; --j) k[j] = k[j - 1];
        k[j] = v;
    }
    return k;
}

struct BoundaryEntry {
    FaceKey key;
    FaceKind kind;
    index_t face;
};

using FaceOwners = std::array<std::vector<CellFaceRef>, kFaceKindCount>;

// The boundary faces `take_face` accepts, each with the first face of a cell `take_cell`
// accepts that has its nodes.
template <class TakeFace, class TakeCell>
FaceOwners cell_faces(const HybridMesh& mesh, TakeFace take_face, TakeCell take_cell) {
    // Boundary faces are few next to cell faces: sort them once and look every cell face up.
    std::vector<BoundaryEntry> boundary;
    FaceOwners owner;
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad}) {
        const index_t n = mesh.face_count(k);
        owner[static_cast<int>(k)].assign(n, CellFaceRef{CellKind::Tet, kNoIndex, 0});
        for (index_t f = 0; f < n; ++f)
            if (take_face(k, f)) boundary.push_back({make_key(mesh.face(k, f), face_size(k)), k, f});
    }
    if (boundary.empty()) return owner;
    std::sort(boundary.begin(), boundary.end(),
              [](const BoundaryEntry& a, const BoundaryEntry& b) { return a.key < b.key; });

    for (CellKind kind : kAllCellKinds) {
        const CellTopology& topo = topology(kind);
        for (index_t c = 0; c < mesh.cell_count(kind); ++c) {
            if (!take_cell(kind, c)) continue;
            const auto cell = mesh.cell(kind, c);
            for (std::uint8_t lf = 0; lf < topo.face_count; ++lf) {
                const LocalFace& face = topo.face[lf];
                std::array<index_t, 4> nodes{};
                for (int i = 0; i < face.size; ++i) nodes[i] = cell[face.node[i]];
                const FaceKey key = make_key(nodes, face.size);
                auto [first, last] = std::equal_range(
                    boundary.begin(), boundary.end(), BoundaryEntry{key, FaceKind::Tri, 0},
                    [](const BoundaryEntry& a, const BoundaryEntry& b) { return a.key < b.key; });
                for (auto it = first; it != last; ++it) {
                    CellFaceRef& ref = owner[static_cast<int>(it->kind)][it->face];
                    if (ref.cell == kNoIndex) ref = {kind, c, lf};
                }
            }
        }
    }
    return owner;
}

}  // namespace

FaceOwners boundary_cell_faces(const HybridMesh& mesh) {
    return cell_faces(mesh, [](FaceKind, index_t) { return true; }, [](CellKind, index_t) { return true; });
}

FaceOwners region_cell_faces(const HybridMesh& mesh, index_t region, std::span<const index_t> groups) {
    std::vector<char> in_groups(mesh.surface_group_names.size(), 0);
    for (index_t g : groups) in_groups[g] = 1;
    return cell_faces(
        mesh, [&](FaceKind k, index_t f) { return in_groups[mesh.block(k).group[f]] != 0; },
        [&](CellKind k, index_t c) { return mesh.block(k).region[c] == region; });
}

}  // namespace tubemesh::io
