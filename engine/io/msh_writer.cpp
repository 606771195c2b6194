// Gmsh MSH 4.1 writer, ASCII and binary. The file layout is described in msh_format.hpp.
#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/io/group_order.hpp"
#include "engine/io/layout_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/io/mesh_notes.hpp"
#include "engine/io/msh_format.hpp"

namespace tubemesh {

namespace io {
namespace {

struct BoundingBox {
    std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
    bool empty = true;

    void add(const Vec3& p) {
        const std::array<double, 3> c{p.x, p.y, p.z};
        for (int k = 0; k < 3; ++k) {
            lo[k] = empty ? c[k] : std::min(lo[k], c[k]);
            hi[k] = empty ? c[k] : std::max(hi[k], c[k]);
        }
        empty = false;
    }
};

// One box per group over the nodes of the group's elements (Gmsh wants one per entity).
void add_boxes(const HybridMesh& mesh, const std::vector<index_t>& nodes, const std::vector<index_t>& ids,
               std::size_t stride, std::vector<BoundingBox>& boxes) {
    for (std::size_t e = 0; e < ids.size(); ++e)
        for (std::size_t k = 0; k < stride; ++k) boxes[ids[e]].add(mesh.point(nodes[e * stride + k]));
}

// Gmsh reads names between double quotes on one line and keeps at most 127 characters.
void check_name(const std::string& name, const char* what, const AtomicFile& out) {
    const bool bad_char = name.find_first_of("\"\r\n") != std::string::npos;
    if (bad_char || name.size() > kMshMaxNameLength)
        throw Error("cannot write '" + out.target().string() + "': " + what + " name \"" + name + "\" " +
                    (bad_char ? "contains a double quote or a line break" : "is longer than 127 characters") +
                    ", which Gmsh files cannot hold");
}

int entity_tag(std::size_t id, const AtomicFile& out) {
    if (id >= static_cast<std::size_t>(INT_MAX))
        throw Error("cannot write '" + out.target().string() + "': too many regions or surface groups for Gmsh");
    return static_cast<int>(id) + 1;
}

class MshWriter {
public:
    MshWriter(const HybridMesh& mesh, AtomicFile& out, bool binary, const MeshDescription* description)
        : mesh_(mesh), out_(out), binary_(binary), description_(description) {}

    void write() {
        mesh_format();
        comments();
        physical_names();
        entities();
        nodes();
        elements();
    }

private:
    // Volume entity 1 always exists: the node block lives there.
    std::size_t volume_entity_count() const { return std::max<std::size_t>(1, mesh_.region_names.size()); }

    void mesh_format() {
        out_.write(binary_ ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n");
        if (binary_) {
            out_.write_raw(int{1});  // lets a reader detect the byte order
            out_.write("\n");
        }
        out_.write("$EndMeshFormat\n");
    }

    // Gmsh and meshio skip a section they do not know; this one tells a reader the length unit
    // and where each surface group is. Always text.
    void comments() {
        out_.write("$Comments\n");
        for (const std::string& line : mesh_notes(mesh_, description_)) {
            out_.write(line);
            out_.write("\n");
        }
        out_.write("$EndComments\n");
    }

    // Always text, also in binary files.
    void physical_names() {
        const std::size_t count = mesh_.region_names.size() + mesh_.surface_group_names.size();
        if (count == 0) return;
        out_.write("$PhysicalNames\n");
        out_.write_number(count);
        out_.write("\n");
        auto put = [&](int dim, std::size_t id, const std::string& name, const char* what) {
            check_name(name, what, out_);
            out_.write_number(dim);
            out_.write(" ");
            out_.write_number(entity_tag(id, out_));
            out_.write(" \"");
            out_.write(name);
            out_.write("\"\n");
        };
        for (std::size_t g = 0; g < mesh_.surface_group_names.size(); ++g)
            put(2, g, mesh_.surface_group_names[g], "surface group");
        for (std::size_t r = 0; r < mesh_.region_names.size(); ++r) put(3, r, mesh_.region_names[r], "region");
        out_.write("$EndPhysicalNames\n");
    }

    void entities() {
        std::vector<BoundingBox> surface_boxes(mesh_.surface_group_names.size());
        for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
            add_boxes(mesh_, mesh_.block(k).nodes, mesh_.block(k).group, static_cast<std::size_t>(face_size(k)),
                      surface_boxes);
        std::vector<BoundingBox> volume_boxes(volume_entity_count());
        for (CellKind k : kAllCellKinds)
            add_boxes(mesh_, mesh_.block(k).nodes, mesh_.block(k).region, static_cast<std::size_t>(node_count(k)),
                      volume_boxes);

        section_start("$Entities");
        size_value(0);  // points
        size_value(0);  // curves
        size_value(surface_boxes.size());
        size_value(volume_boxes.size());
        end_line();
        for (std::size_t g = 0; g < surface_boxes.size(); ++g) entity(g, surface_boxes[g], true);
        for (std::size_t r = 0; r < volume_boxes.size(); ++r)
            entity(r, volume_boxes[r], r < mesh_.region_names.size());
        section_end("$EndEntities");
    }

    // tag, box, physical tags, bounding entities (none: the B-rep topology is not kept).
    void entity(std::size_t id, const BoundingBox& box, bool has_physical) {
        const int tag = entity_tag(id, out_);
        int_value(tag);
        for (double v : box.lo) double_value(v);
        for (double v : box.hi) double_value(v);
        size_value(has_physical ? 1 : 0);
        if (has_physical) int_value(tag);
        size_value(0);
        end_line();
    }

    void nodes() {
        const std::uint64_t n = mesh_.point_count();
        section_start("$Nodes");
        size_value(n == 0 ? 0 : 1);
        size_value(n);
        size_value(n == 0 ? 0 : 1);
        size_value(n);
        end_line();
        if (n > 0) {
            int_value(3);
            int_value(1);
            int_value(0);  // no parametric coordinates
            size_value(n);
            end_line();
            for (std::uint64_t i = 0; i < n; ++i) {
                size_value(i + 1);
                end_line();
            }
            for (index_t i = 0; i < n; ++i) {
                double_value(mesh_.x[i]);
                double_value(mesh_.y[i]);
                double_value(mesh_.z[i]);
                end_line();
            }
        }
        section_end("$EndNodes");
    }

    struct BlockInfo {
        const std::vector<index_t>* nodes;
        const std::vector<index_t>* ids;
        std::size_t stride;
        int type;
        int dimension;
        std::size_t group_count;
    };

    std::array<BlockInfo, kMshKindCount> blocks() const {
        std::array<BlockInfo, kMshKindCount> b{};
        for (CellKind k : kAllCellKinds)
            b[msh_kind_index(k)] = {&mesh_.block(k).nodes, &mesh_.block(k).region,
                                    static_cast<std::size_t>(node_count(k)), msh_type(k), 3,
                                    mesh_.region_names.size()};
        for (FaceKind k : {FaceKind::Tri, FaceKind::Quad})
            b[msh_kind_index(k)] = {&mesh_.block(k).nodes, &mesh_.block(k).group,
                                    static_cast<std::size_t>(face_size(k)), msh_type(k), 2,
                                    mesh_.surface_group_names.size()};
        return b;
    }

    void elements() {
        const auto info = blocks();
        std::array<GroupOrder, kMshKindCount> orders;
        std::uint64_t total = 0, block_count = 0;
        for (int k = 0; k < kMshKindCount; ++k) {
            orders[k] = order_by_group(*info[k].ids, info[k].group_count);
            for (std::size_t g = 0; g < info[k].group_count; ++g) block_count += orders[k].group(g).empty() ? 0 : 1;
            total += info[k].ids->size();
        }
        section_start("$Elements");
        size_value(block_count);
        size_value(total);
        size_value(total == 0 ? 0 : 1);
        size_value(total);
        end_line();
        std::uint64_t first_tag = 1;  // of the current kind; tags follow the kinds' order
        for (int k = 0; k < kMshKindCount; ++k) {
            for (std::size_t g = 0; g < info[k].group_count; ++g)
                element_block(info[k], g, orders[k].group(g), first_tag);
            first_tag += info[k].ids->size();
        }
        section_end("$EndElements");
    }

    void element_block(const BlockInfo& b, std::size_t group, std::span<const index_t> elements,
                       std::uint64_t first_tag) {
        if (elements.empty()) return;
        int_value(b.dimension);
        int_value(entity_tag(group, out_));
        int_value(b.type);
        size_value(elements.size());
        end_line();
        for (index_t e : elements) {
            size_value(first_tag + e);
            for (std::size_t k = 0; k < b.stride; ++k) size_value(std::uint64_t{(*b.nodes)[e * b.stride + k]} + 1);
            end_line();
        }
    }

    // Section markers are text on their own lines in both encodings.
    void section_start(const char* name) {
        out_.write(name);
        out_.write("\n");
    }
    void section_end(const char* name) {
        if (binary_) out_.write("\n");
        out_.write(name);
        out_.write("\n");
    }

    // One value: raw bytes in binary files, space-separated text in ASCII ones.
    template <class T>
    void value(T v) {
        if (binary_) {
            out_.write_raw(v);
            return;
        }
        if (!line_start_) out_.write(" ");
        out_.write_number(v);
        line_start_ = false;
    }
    void size_value(std::uint64_t v) { value(v); }  // MSH "size_t", 8 bytes as declared in the header
    void int_value(int v) { value(v); }
    void double_value(double v) { value(v); }
    void end_line() {
        if (!binary_) out_.write("\n");
        line_start_ = true;
    }

    const HybridMesh& mesh_;
    AtomicFile& out_;
    bool binary_;
    const MeshDescription* description_;
    bool line_start_ = true;
};

}  // namespace
}  // namespace io

void write_msh(const HybridMesh& mesh, const std::filesystem::path& path, MshEncoding encoding,
               const MeshDescription* description) {
    io::check_layout_for_writing(mesh, path);
    io::AtomicFile out(path);
    io::MshWriter(mesh, out, encoding == MshEncoding::Binary, description).write();
    out.commit();
}

}  // namespace tubemesh
