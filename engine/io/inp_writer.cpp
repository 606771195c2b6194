// Abaqus input file (.inp) writer: the mesh part of a model, ready for *INCLUDE.
//
//   *NODE                        node i is label i + 1
//   *ELEMENT, TYPE=C3D4|C3D5|C3D8, ELSET=KIND_C3D4|...   labels: tets, then pyramids, hexes
//   *ELSET per volume region     (region name made a valid label, see abaqus_names.hpp)
//   *NSET per surface group      the group's nodes, ascending
//   *SURFACE, TYPE=ELEMENT per surface group: one "element, Sn" line per boundary face, the
//                                cell face carrying it (face numbers: abaqus_faces.hpp)
// Node orders of C3D4, C3D5 and C3D8 are the VTK ones, so nothing is permuted. Regions and
// groups without elements are left out: Abaqus rejects empty surfaces.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/io/abaqus_faces.hpp"
#include "engine/io/abaqus_names.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/boundary_cell_faces.hpp"
#include "engine/io/group_order.hpp"
#include "engine/io/layout_check.hpp"
#include "engine/io/mesh_io.hpp"

namespace tubemesh {

namespace io {
namespace {

constexpr const char* abaqus_type(CellKind k) {
    return k == CellKind::Tet ? "C3D4" : k == CellKind::Pyramid ? "C3D5" : "C3D8";
}

using FaceOwners = std::array<std::vector<CellFaceRef>, kFaceKindCount>;

// Comma-separated labels, 16 to a line (the most Abaqus reads on one data line).
class LabelList {
public:
    explicit LabelList(AtomicFile& out) : out_(out) {}

    void add(std::uint64_t label) {
        if (on_line_ == 16) end_line();
        if (on_line_ > 0) out_.write(", ");
        out_.write_number(label);
        ++on_line_;
    }
    void finish() {
        if (on_line_ > 0) end_line();
    }

private:
    void end_line() {
        out_.write("\n");
        on_line_ = 0;
    }
    AtomicFile& out_;
    int on_line_ = 0;
};

class InpWriter {
public:
    InpWriter(const HybridMesh& mesh, const FaceOwners& owners, AtomicFile& out)
        : mesh_(mesh), owners_(owners), out_(out) {
        std::uint64_t next = 1;
        for (CellKind k : kAllCellKinds) {
            first_label_[static_cast<int>(k)] = next;
            next += mesh_.cell_count(k);
        }
        // Regions first, so they keep their names if a kind set's name clashes.
        AbaqusLabels element_sets;
        for (const std::string& name : mesh_.region_names) region_label_.push_back(element_sets.label(name));
        for (CellKind k : kAllCellKinds)
            kind_label_[static_cast<int>(k)] = element_sets.label(std::string("KIND_") + abaqus_type(k));
        AbaqusLabels surfaces;  // node sets and surfaces have namespaces of their own: same labels
        for (const std::string& name : mesh_.surface_group_names) group_label_.push_back(surfaces.label(name));
    }

    void write() {
        heading();
        nodes();
        for (CellKind k : kAllCellKinds) elements(k);
        region_sets();
        group_sets();
    }

private:
    std::uint64_t label(CellKind k, index_t cell) const { return first_label_[static_cast<int>(k)] + cell; }

    void heading() {
        out_.write("*HEADING\ntubemesh hybrid mesh:");
        for (CellKind k : kAllCellKinds) {
            out_.write(" ");
            out_.write_number(mesh_.cell_count(k));
            out_.write(" ");
            out_.write(abaqus_type(k));
        }
        out_.write("\n** Regions are element sets; surface groups are node sets and element-based surfaces.\n");
    }

    void nodes() {
        out_.write("*NODE\n");
        for (index_t i = 0; i < mesh_.point_count(); ++i) {
            out_.write_number(std::uint64_t{i} + 1);
            for (double c : {mesh_.x[i], mesh_.y[i], mesh_.z[i]}) {
                out_.write(", ");
                out_.write_number(c);
            }
            out_.write("\n");
        }
    }

    void elements(CellKind k) {
        if (mesh_.cell_count(k) == 0) return;
        out_.write("*ELEMENT, TYPE=");
        out_.write(abaqus_type(k));
        out_.write(", ELSET=");
        out_.write(kind_label_[static_cast<int>(k)]);
        out_.write("\n");
        for (index_t c = 0; c < mesh_.cell_count(k); ++c) {
            out_.write_number(label(k, c));
            for (index_t node : mesh_.cell(k, c)) {
                out_.write(", ");
                out_.write_number(std::uint64_t{node} + 1);
            }
            out_.write("\n");
        }
    }

    void region_sets() {
        std::array<GroupOrder, kCellKindCount> by_region;
        for (CellKind k : kAllCellKinds)
            by_region[static_cast<int>(k)] = order_by_group(mesh_.block(k).region, mesh_.region_names.size());
        for (std::size_t r = 0; r < mesh_.region_names.size(); ++r) {
            bool empty = true;
            for (const GroupOrder& g : by_region) empty = empty && g.group(r).empty();
            if (empty) continue;
            out_.write("*ELSET, ELSET=");
            out_.write(region_label_[r]);
            out_.write("\n");
            LabelList list(out_);
            for (CellKind k : kAllCellKinds)
                for (index_t c : by_region[static_cast<int>(k)].group(r)) list.add(label(k, c));
            list.finish();
        }
    }

    void group_sets() {
        std::array<GroupOrder, kFaceKindCount> by_group;
        for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
            by_group[static_cast<int>(k)] = order_by_group(mesh_.block(k).group, mesh_.surface_group_names.size());
        std::vector<index_t> nodes;  // scratch, reused for every group
        for (std::size_t g = 0; g < mesh_.surface_group_names.size(); ++g) {
            nodes.clear();
            for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
                for (index_t f : by_group[static_cast<int>(k)].group(g))
                    for (index_t n : mesh_.face(k, f)) nodes.push_back(n);
            if (nodes.empty()) continue;
            std::sort(nodes.begin(), nodes.end());
            nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());

            out_.write("*NSET, NSET=");
            out_.write(group_label_[g]);
            out_.write("\n");
            LabelList list(out_);
            for (index_t n : nodes) list.add(std::uint64_t{n} + 1);
            list.finish();

            out_.write("*SURFACE, NAME=");
            out_.write(group_label_[g]);
            out_.write(", TYPE=ELEMENT\n");
            for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
                for (index_t f : by_group[static_cast<int>(k)].group(g)) surface_line(owners_[static_cast<int>(k)][f]);
        }
    }

    void surface_line(const CellFaceRef& ref) {
        out_.write_number(label(ref.kind, ref.cell));
        out_.write(", S");
        out_.write_number(abaqus_face_number(ref.kind, ref.local_face));
        out_.write("\n");
    }

    const HybridMesh& mesh_;
    const FaceOwners& owners_;
    AtomicFile& out_;
    std::array<std::uint64_t, kCellKindCount> first_label_{};
    std::array<std::string, kCellKindCount> kind_label_;
    std::vector<std::string> region_label_;
    std::vector<std::string> group_label_;
};

// An element-based surface can only name faces that some cell has.
void check_owners(const HybridMesh& mesh, const FaceOwners& owners, const std::filesystem::path& path) {
    for (FaceKind k : {FaceKind::Tri, FaceKind::Quad}) {
        const auto& o = owners[static_cast<int>(k)];
        for (index_t f = 0; f < o.size(); ++f)
            if (o[f].cell == kNoIndex)
                throw Error("cannot write '" + path.string() + "': boundary " +
                            (k == FaceKind::Tri ? "triangle " : "quad ") + std::to_string(f) + " (surface group \"" +
                            mesh.surface_group_names[mesh.block(k).group[f]] +
                            "\") is not a face of any cell, so an Abaqus element surface cannot hold it");
    }
}

}  // namespace
}  // namespace io

void write_inp(const HybridMesh& mesh, const std::filesystem::path& path) {
    io::check_layout_for_writing(mesh, path);
    const io::FaceOwners owners = io::boundary_cell_faces(mesh);
    io::check_owners(mesh, owners, path);
    io::AtomicFile out(path);
    io::InpWriter(mesh, owners, out).write();
    out.commit();
}

}  // namespace tubemesh
