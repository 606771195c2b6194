// Abaqus / CalculiX input file (.inp) writer: the mesh part of a model, ready for *INCLUDE.
//
//   ** comment block          unit, element types, surface groups (mesh_notes.hpp), set names
//   *NODE                     node i is label i + 1; numbers in at most 20 characters
//   *ELEMENT per kind         labels: tets, then pyramids, hexes; ELSET KIND_TET / _PYRAMID / _HEX
//   *ELSET EALL, *NSET NALL   every element, every node (as ranges)
//   *ELSET per volume region  (region name made a valid label, see abaqus_names.hpp)
//   per region surface R      *NSET R, *ELSET R_S1 ... R_S6, *SURFACE R as a group's below, the
//                             faces taken from R's region's elements (an assembly solid's top)
//   per surface group G       *NSET G (its nodes); *ELSET G_S1 ... G_S6, the elements whose face
//                             S1 ... S6 lies on G (what CalculiX's *FILM, *DFLUX and *DLOAD
//                             take: "G_S3, F3, ..."); *SURFACE G, TYPE=ELEMENT from those sets
//   per alias A of a group G  the same sets and surface under A (a built block's "top", ...)
//   *NSET per named node set  each pipe's inlet and outlet rim (MeshDescription)
//   *NSET SHARED_A_B          the nodes groups A and B share: a fixed value on both A and B
//                             is given twice there
//   with pipe_network.write   the water networks after all that, and their films beside the
//                             file (inp_network.hpp)
// Node orders of C3D4, C3D5 and C3D8 are the VTK ones, so nothing is permuted; a pyramid as a
// collapsed C3D8 repeats its apex four times. Sets without members are left out: Abaqus
// rejects empty surfaces.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/io/abaqus_faces.hpp"
#include "engine/io/abaqus_names.hpp"
#include "engine/io/abaqus_number.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/boundary_cell_faces.hpp"
#include "engine/io/group_order.hpp"
#include "engine/io/inp_network.hpp"
#include "engine/io/layout_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/io/mesh_notes.hpp"
#include "engine/mesh/surface_groups.hpp"

namespace tubemesh {

namespace io {
namespace {

constexpr double kRoundOff = 1e-12;  // relative to the model's largest extent
constexpr int kFaceNumbers = 6;      // S1 ... S6

using FaceOwners = std::array<std::vector<CellFaceRef>, kFaceKindCount>;

std::string element_type(CellKind k, const WriteOptions& o) {
    const bool collapsed = k == CellKind::Pyramid && o.inp_pyramid == InpPyramid::CollapsedHex;
    const std::string shape = k == CellKind::Tet ? "C3D4" : (k == CellKind::Hex || collapsed) ? "C3D8" : "C3D5";
    switch (o.inp_family) {
        case InpFamily::Stress: return shape;
        case InpFamily::HeatTransfer: return "D" + shape;
        case InpFamily::Coupled: return shape;
        case InpFamily::CoupledAbaqus: return shape + "T";
    }
    return shape;
}

const char* kind_set(CellKind k) {
    return k == CellKind::Tet ? "KIND_TET" : k == CellKind::Pyramid ? "KIND_PYRAMID" : "KIND_HEX";
}

// Comma-separated labels, 16 to a line (the most Abaqus reads on one data line).
class LabelList {
public:
    explicit LabelList(AtomicFile& out) : out_(out) {}
    ~LabelList() { finish(); }

    void add(std::uint64_t label) {
        separate();
        out_.write_number(label);
    }
    void finish() {
        if (on_line_ > 0) out_.write("\n");
        on_line_ = 0;
    }

private:
    void separate() {
        if (on_line_ == 16) finish();
        if (on_line_ > 0) out_.write(", ");
        ++on_line_;
    }
    AtomicFile& out_;
    int on_line_ = 0;
};

// Per surface group: the element labels whose face S1..S6 carries a boundary face of it.
using FaceSets = std::vector<std::array<std::vector<std::uint64_t>, kFaceNumbers>>;

class InpWriter {
public:
    InpWriter(const HybridMesh& mesh, const FaceOwners& owners, const WriteOptions& options, AtomicFile& out)
        : mesh_(mesh), options_(options), out_(out) {
        std::uint64_t next = 1;
        for (CellKind k : kAllCellKinds) {
            first_label_[static_cast<int>(k)] = next;
            next += mesh_.cell_count(k);
        }
        // Element sets: the fixed names first, so a region or group named like them is renamed.
        for (const char* fixed : {"EALL", "KIND_TET", "KIND_PYRAMID", "KIND_HEX"}) element_sets_.label(fixed);
        node_sets_.label("NALL");
        for (const std::string& name : mesh_.region_names) region_label_.push_back(element_sets_.label(name));
        face_sets_ = face_sets(owners);
        group_nodes_ = surface_group_nodes(mesh_);
        for (std::size_t g = 0; g < mesh_.surface_group_names.size(); ++g) groups_.push_back(labels_of(g));
        zero_below_ = kRoundOff * model_extent();
    }

    void write() {
        notes();
        out_.write("*HEADING\ntubemesh hybrid mesh\n");
        nodes();
        for (CellKind k : kAllCellKinds) elements(k);
        all_sets();
        region_sets();
        region_surfaces();
        for (std::size_t g = 0; g < mesh_.surface_group_names.size(); ++g) group_sets(g);
        named_node_sets();
        shared_node_sets();
    }

    // What the mesh part used, for what follows it (the water networks).
    InpNumbering numbering() {
        return {mesh_.point_count(), mesh_.cell_count(), element_sets_, node_sets_, zero_below_};
    }

private:
    // The labels of one surface group's sets, and of its alias's; empty where a set has no member.
    struct GroupLabels {
        std::string name;  // node set and surface
        std::array<std::string, kFaceNumbers> face_set;
        std::string alias;
        std::array<std::string, kFaceNumbers> alias_face_set;
    };

    GroupLabels labels_of(std::size_t g) {
        GroupLabels l;
        l.name = node_sets_.label(mesh_.surface_group_names[g]);
        surfaces_.label(l.name);
        const MeshDescription* d = options_.description;
        if (d && d->group(g) && !d->group(g)->alias.empty()) {
            l.alias = node_sets_.label(d->group(g)->alias);
            surfaces_.label(l.alias);
        }
        for (int s = 0; s < kFaceNumbers; ++s) {
            if (face_sets_[g][static_cast<std::size_t>(s)].empty()) continue;
            l.face_set[static_cast<std::size_t>(s)] = element_sets_.label(l.name + "_S" + std::to_string(s + 1));
            if (!l.alias.empty())
                l.alias_face_set[static_cast<std::size_t>(s)] = element_sets_.label(l.alias + "_S" + std::to_string(s + 1));
        }
        return l;
    }

    std::uint64_t label(CellKind k, index_t cell) const { return first_label_[static_cast<int>(k)] + cell; }
    bool collapsed() const { return options_.inp_pyramid == InpPyramid::CollapsedHex; }

    double model_extent() const {
        double extent = 0;
        for (const std::vector<double>* c : {&mesh_.x, &mesh_.y, &mesh_.z}) {
            if (c->empty()) continue;
            const auto [lo, hi] = std::minmax_element(c->begin(), c->end());
            extent = std::max({extent, std::abs(*lo), std::abs(*hi)});
        }
        return extent;
    }

    FaceSets face_sets(const FaceOwners& owners) const {
        FaceSets sets(mesh_.surface_group_names.size());
        for (FaceKind k : {FaceKind::Tri, FaceKind::Quad}) {
            const FaceBlock& faces = mesh_.block(k);
            for (std::size_t f = 0; f < faces.group.size(); ++f) {
                const CellFaceRef& ref = owners[static_cast<int>(k)][f];
                const int s = abaqus_face_number(ref.kind, ref.local_face, collapsed());
                sets[faces.group[f]][static_cast<std::size_t>(s - 1)].push_back(label(ref.kind, ref.cell));
            }
        }
        for (auto& group : sets)
            for (auto& labels : group) std::sort(labels.begin(), labels.end());
        return sets;
    }

    void comment(const std::string& text) {
        out_.write("** ");
        out_.write(text);
        out_.write("\n");
    }

    void notes() {
        comment("tubemesh hybrid mesh for Abaqus and CalculiX, to *INCLUDE in a deck");
        for (const std::string& line : mesh_notes(mesh_, options_.description)) comment(line);
        std::string types = "elements:";
        for (CellKind k : kAllCellKinds) {
            types += ' ';
            types += std::to_string(mesh_.cell_count(k));
            types += std::string(" ") + topology(k).name + " " + element_type(k, options_);
            if (k != CellKind::Hex) types += ',';
        }
        comment(types);
        if (collapsed())
            comment("pyramids are bricks with the apex repeated (nodes 1 2 3 4 5 5 5 5): base S1, sides S3 S4 S5 S6");
        else if (mesh_.cell_count(CellKind::Pyramid) > 0)
            comment("C3D5 is for Abaqus: CalculiX has no 5-node pyramid and refuses the file");
        if (options_.inp_family == InpFamily::Coupled)
            comment("coupled temperature-displacement for CalculiX: its *COUPLED TEMPERATURE-DISPLACEMENT step gives "
                    "C3D4 / C3D8 the temperature (DOF 11); Abaqus needs --inp-family coupled-abaqus (C3D4T / C3D8T)");
        else if (options_.inp_family == InpFamily::CoupledAbaqus)
            comment("C3D4T / C3D8T are for Abaqus: CalculiX refuses them (--inp-family coupled writes its C3D4 / C3D8)");
        comment("sets: EALL every element, NALL every node, KIND_TET / KIND_PYRAMID / KIND_HEX, one element set per "
                "region");
        comment("per surface group G: node set G, element sets G_S1 ... G_S6 (the elements whose face Sk lies on G)");
        comment("and the element surface G; for CalculiX's *FILM / *DFLUX write one line per set, e.g. \"G_S3, F3, ...\"");
        comment("SHARED_A_B: the nodes groups A and B share (a value fixed on both A and B is given twice there)");
        for (const GroupLabels& l : groups_) {
            std::string sets;
            for (const std::string& set : l.face_set)
                if (!set.empty()) sets += " " + set;
            if (!sets.empty()) comment(l.name + (l.alias.empty() ? "" : " = " + l.alias) + ":" + sets);
        }
    }

    void number(double v) {
        char text[32];
        out_.write_bytes(text, abaqus_number(v, zero_below_, text));
    }

    void nodes() {
        out_.write("*NODE\n");
        for (index_t i = 0; i < mesh_.point_count(); ++i) {
            out_.write_number(std::uint64_t{i} + 1);
            for (double c : {mesh_.x[i], mesh_.y[i], mesh_.z[i]}) {
                out_.write(", ");
                number(c);
            }
            out_.write("\n");
        }
    }

    void elements(CellKind k) {
        if (mesh_.cell_count(k) == 0) return;
        out_.write("*ELEMENT, TYPE=");
        out_.write(element_type(k, options_));
        out_.write(", ELSET=");
        out_.write(kind_set(k));
        out_.write("\n");
        const bool repeat_apex = k == CellKind::Pyramid && collapsed();
        for (index_t c = 0; c < mesh_.cell_count(k); ++c) {
            out_.write_number(label(k, c));
            const std::span<const index_t> nodes = mesh_.cell(k, c);
            for (index_t node : nodes) {
                out_.write(", ");
                out_.write_number(std::uint64_t{node} + 1);
            }
            for (int r = 0; repeat_apex && r < 3; ++r) {
                out_.write(", ");
                out_.write_number(std::uint64_t{nodes[4]} + 1);
            }
            out_.write("\n");
        }
    }

    // Ranges, not set names: meshio and other readers take a name in a data line for a node
    // or element label of the set it names only in some places.
    void all_sets() {
        const std::uint64_t cells = mesh_.cell_count();
        if (cells > 0) {
            out_.write("*ELSET, ELSET=EALL, GENERATE\n1, ");
            out_.write_number(cells);
            out_.write(", 1\n");
        }
        if (mesh_.point_count() == 0) return;
        out_.write("*NSET, NSET=NALL, GENERATE\n1, ");
        out_.write_number(std::uint64_t{mesh_.point_count()});
        out_.write(", 1\n");
    }

    void region_sets() {
        std::array<GroupOrder, kCellKindCount> by_region;
        for (CellKind k : kAllCellKinds)
            by_region[static_cast<int>(k)] = order_by_group(mesh_.block(k).region, mesh_.region_names.size());
        for (std::size_t r = 0; r < mesh_.region_names.size(); ++r) {
            bool empty = true;
            for (const GroupOrder& g : by_region) empty = empty && g.group(r).empty();
            if (empty) continue;
            element_set_header(region_label_[r]);
            LabelList list(out_);
            for (CellKind k : kAllCellKinds)
                for (index_t c : by_region[static_cast<int>(k)].group(r)) list.add(label(k, c));
        }
    }

    // A surface seen from one region's cells (an assembly solid's top): node set, face sets and
    // surface, as a group's.
    void region_surfaces() {
        if (!options_.description) return;
        for (const RegionSurface& r : options_.description->region_surfaces) {
            const FaceOwners owners = region_cell_faces(mesh_, r.region, r.groups);
            std::array<std::vector<std::uint64_t>, kFaceNumbers> sets;
            std::vector<index_t> nodes;
            for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
                for (index_t f = 0; f < mesh_.face_count(k); ++f) {
                    const CellFaceRef& ref = owners[static_cast<int>(k)][f];
                    if (ref.cell == kNoIndex) continue;
                    const int s = abaqus_face_number(ref.kind, ref.local_face, collapsed());
                    sets[static_cast<std::size_t>(s - 1)].push_back(label(ref.kind, ref.cell));
                    for (index_t n : mesh_.face(k, f)) nodes.push_back(n);
                }
            for (auto& labels : sets) std::sort(labels.begin(), labels.end());
            std::sort(nodes.begin(), nodes.end());
            nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
            const std::string name = node_sets_.label(r.name);
            surfaces_.label(name);
            std::array<std::string, kFaceNumbers> names;
            for (int s = 0; s < kFaceNumbers; ++s)
                if (!sets[static_cast<std::size_t>(s)].empty())
                    names[static_cast<std::size_t>(s)] = element_sets_.label(name + "_S" + std::to_string(s + 1));
            node_set(name, nodes);
            face_sets(names, sets);
            surface(name, names);
        }
    }

    void node_set(const std::string& name, const std::vector<index_t>& nodes) {
        if (nodes.empty()) return;
        out_.write("*NSET, NSET=");
        out_.write(name);
        out_.write("\n");
        LabelList list(out_);
        for (index_t n : nodes) list.add(std::uint64_t{n} + 1);
    }

    // The node set, the face sets and the surface of group g, then the same under its alias.
    void group_sets(std::size_t g) {
        const GroupLabels& l = groups_[g];
        const auto& sets = face_sets_[g];
        node_set(l.name, group_nodes_[g]);
        face_sets(l.face_set, sets);
        surface(l.name, l.face_set);
        if (l.alias.empty()) return;
        node_set(l.alias, group_nodes_[g]);
        face_sets(l.alias_face_set, sets);
        surface(l.alias, l.alias_face_set);
    }

    void face_sets(const std::array<std::string, kFaceNumbers>& names,
                   const std::array<std::vector<std::uint64_t>, kFaceNumbers>& sets) {
        for (int s = 0; s < kFaceNumbers; ++s) {
            const auto& labels = sets[static_cast<std::size_t>(s)];
            if (labels.empty()) continue;
            element_set_header(names[static_cast<std::size_t>(s)]);
            LabelList list(out_);
            for (std::uint64_t label : labels) list.add(label);
        }
    }

    void element_set_header(const std::string& name) {
        out_.write("*ELSET, ELSET=");
        out_.write(name);
        out_.write("\n");
    }

    void surface(const std::string& name, const std::array<std::string, kFaceNumbers>& face_sets) {
        if (std::all_of(face_sets.begin(), face_sets.end(), [](const std::string& f) { return f.empty(); })) return;
        out_.write("*SURFACE, NAME=");
        out_.write(name);
        out_.write(", TYPE=ELEMENT\n");
        for (int s = 0; s < kFaceNumbers; ++s) {
            if (face_sets[static_cast<std::size_t>(s)].empty()) continue;
            out_.write(face_sets[static_cast<std::size_t>(s)]);
            out_.write(", S");
            out_.write_number(s + 1);
            out_.write("\n");
        }
    }

    void named_node_sets() {
        if (!options_.description) return;
        for (const NamedNodeSet& set : options_.description->node_sets) node_set(node_sets_.label(set.name), set.nodes);
    }

    void shared_node_sets() {
        for (const SharedNodes& s : shared_group_nodes(mesh_))
            node_set(node_sets_.label("SHARED_" + groups_[s.a].name + "_" + groups_[s.b].name), s.nodes);
    }

    const HybridMesh& mesh_;
    const WriteOptions& options_;
    AtomicFile& out_;
    std::array<std::uint64_t, kCellKindCount> first_label_{};
    AbaqusLabels element_sets_, node_sets_, surfaces_;
    std::vector<std::string> region_label_;
    FaceSets face_sets_;
    std::vector<std::vector<index_t>> group_nodes_;
    std::vector<GroupLabels> groups_;
    double zero_below_ = 0;
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

void write_inp(const HybridMesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
    io::check_layout_for_writing(mesh, path);
    if (options.inp_pyramid == InpPyramid::C3D5 && options.inp_family != InpFamily::Stress &&
        mesh.cell_count(CellKind::Pyramid) > 0)
        throw Error("cannot write '" + path.string() +
                    "': the 5-node pyramid C3D5 has no heat-transfer or coupled variant; write pyramids as "
                    "collapsed bricks (the default)");
    const io::FaceOwners owners = io::boundary_cell_faces(mesh);
    io::check_owners(mesh, owners, path);
    io::AtomicFile out(path);
    io::InpWriter writer(mesh, owners, options, out);
    writer.write();
    if (options.pipe_network.write) {
        io::AtomicFile films(io::films_path(path));
        io::write_pipe_networks(mesh, owners, options, writer.numbering(), out, films);
        films.commit();
    }
    out.commit();
}

}  // namespace tubemesh
