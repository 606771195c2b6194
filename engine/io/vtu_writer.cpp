// VTK XML UnstructuredGrid (.vtu) writer for ParaView and meshio.
//
// Encoding: every DataArray is format="binary" inline: one base64 stream of a UInt64 byte
// count followed by the little-endian values (header_type="UInt64", no compression). VTK and
// meshio both read this form; raw appended data would be smaller but is not valid XML, which
// trips up generic XML tools.
//
// Content: one piece with the volume cells (tets, pyramids, hexes) followed by the boundary
// faces (triangles, then quads), each kind in mesh order, so the surface groups - the tube
// walls pipe_k, the other B-rep faces face_k - are in the file as well as the regions.
// All groups share one numbering, regions first: group r is region_names[r] and group R + g
// is surface_group_names[g] (R regions), so one Threshold on "group" shows one group.
// Cell data:
//   dim      UInt8   3 volume cell, 2 boundary face (Threshold dim 3..3: the volume alone)
//   kind     UInt8   0 tetrahedron, 1 pyramid, 2 hexahedron (CellKind), 3 triangle, 4 quad
//   group    UInt32  the group id above
//   quality  Float64 cells: the primary measure (tet collapse, pyramid / hex scaled Jacobian);
//                    a boundary face repeats the value of the cell it bounds (NaN if no cell
//                    has it, as in partial meshes), so colouring by quality shows the same
//                    colours outside whether the faces are drawn or hidden
// Field data (before the piece): one Int32 array per group, named after the group, holding
// (group id, dim) - the form meshio gives Gmsh physical groups (field_data[name] = [tag,
// dim]). VTK keys field arrays by name, so a name already used by an earlier group gets
// "_2", "_3", ... appended. An XML comment at the top lists the same table.
#include <array>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/io/base64_writer.hpp"
#include "engine/io/boundary_cell_faces.hpp"
#include "engine/io/layout_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh {

namespace io {
namespace {

constexpr std::uint8_t vtk_cell_type(CellKind k) {
    return k == CellKind::Tet ? 10 : k == CellKind::Pyramid ? 14 : 12;
}
constexpr std::uint8_t vtk_cell_type(FaceKind k) { return k == FaceKind::Tri ? 5 : 9; }

// "kind" values: the cell kinds, then the face kinds.
constexpr std::uint8_t kind_value(CellKind k) { return static_cast<std::uint8_t>(k); }
constexpr std::uint8_t kind_value(FaceKind k) {
    return static_cast<std::uint8_t>(kCellKindCount + static_cast<int>(k));
}

constexpr std::array<FaceKind, kFaceKindCount> kAllFaceKinds = {FaceKind::Tri, FaceKind::Quad};

// XML comments may not contain "--".
std::string comment_safe(const std::string& text) {
    std::string s;
    for (char c : text) {
        if (c == '-' && !s.empty() && s.back() == '-') s += ' ';
        s += c;
    }
    return s;
}

// Text inside a double-quoted XML attribute.
std::string attribute_safe(const std::string& text) {
    std::string s;
    for (char c : text) {
        switch (c) {
            case '&': s += "&amp;"; break;
            case '<': s += "&lt;"; break;
            case '>': s += "&gt;"; break;
            case '"': s += "&quot;"; break;
            case '\n': s += "&#10;"; break;
            case '\r': s += "&#13;"; break;
            case '\t': s += "&#9;"; break;
            default: s += c;
        }
    }
    return s;
}

struct VtuGroup {
    std::string name;        // as in the mesh
    std::string field_name;  // distinct over all groups
    std::uint8_t dim;
};

// Regions, then surface groups: index = group id.
std::vector<VtuGroup> group_table(const HybridMesh& mesh) {
    std::vector<VtuGroup> groups;
    std::set<std::string> taken;
    auto add = [&](const std::string& name, std::uint8_t dim) {
        std::string field = name;
        for (int n = 2; !taken.insert(field).second; ++n) field = name + "_" + std::to_string(n);
        groups.push_back({name, field, dim});
    };
    for (const std::string& r : mesh.region_names) add(r, 3);
    for (const std::string& g : mesh.surface_group_names) add(g, 2);
    return groups;
}

using CellQuality = std::array<std::vector<double>, kCellKindCount>;  // per kind, in cell order
using FaceQuality = std::array<std::vector<double>, kFaceKindCount>;

// Per face kind, in face order: the quality of the cell that has the face (NaN if none).
FaceQuality face_quality(const HybridMesh& mesh, const CellQuality& cell) {
    const auto owners = boundary_cell_faces(mesh);
    FaceQuality q;
    for (FaceKind k : kAllFaceKinds)
        for (const CellFaceRef& ref : owners[static_cast<int>(k)])
            q[static_cast<int>(k)].push_back(ref.cell == kNoIndex ? std::numeric_limits<double>::quiet_NaN()
                                                                  : cell[static_cast<int>(ref.kind)][ref.cell]);
    return q;
}

// One block of the piece: the elements of one cell or face kind.
struct Block {
    const std::vector<index_t>* nodes;
    int size;  // nodes per element
    std::uint8_t vtk_type;
    std::uint8_t kind;  // the "kind" value
    std::uint8_t dim;
    const std::vector<index_t>* ids;  // region or surface group per element
    index_t first_group;              // group id of ids' 0
    const std::vector<double>* quality;
    std::size_t count() const { return ids->size(); }
};
using Blocks = std::array<Block, kCellKindCount + kFaceKindCount>;

// Cells, then faces: the element order of the file.
Blocks blocks_of(const HybridMesh& mesh, const CellQuality& cell_quality, const FaceQuality& face_quality) {
    Blocks b{};
    std::size_t i = 0;
    for (CellKind k : kAllCellKinds)
        b[i++] = {&mesh.block(k).nodes, node_count(k), vtk_cell_type(k), kind_value(k), 3,
                  &mesh.block(k).region, 0, &cell_quality[static_cast<int>(k)]};
    const auto first_surface_group = static_cast<index_t>(mesh.region_names.size());
    for (FaceKind k : kAllFaceKinds)
        b[i++] = {&mesh.block(k).nodes, face_size(k), vtk_cell_type(k), kind_value(k), 2,
                  &mesh.block(k).group, first_surface_group, &face_quality[static_cast<int>(k)]};
    return b;
}

class VtuWriter {
public:
    VtuWriter(const HybridMesh& mesh, const CellQuality& cell_quality, const FaceQuality& face_quality,
              AtomicFile& out)
        : mesh_(mesh), groups_(group_table(mesh)), blocks_(blocks_of(mesh, cell_quality, face_quality)), out_(out) {}

    void write() {
        std::uint64_t cells = 0, connectivity = 0;
        for (const Block& k : blocks_) {
            cells += k.count();
            connectivity += k.nodes->size();
        }
        out_.write("<?xml version=\"1.0\"?>\n");
        legend();
        out_.write("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                   "header_type=\"UInt64\">\n  <UnstructuredGrid>\n");
        field_data();
        out_.write("    <Piece NumberOfPoints=\"");
        out_.write_number(mesh_.point_count());
        out_.write("\" NumberOfCells=\"");
        out_.write_number(cells);
        out_.write("\">\n      <Points>\n");
        points();
        out_.write("      </Points>\n      <Cells>\n");
        cell_arrays(cells, connectivity);
        out_.write("      </Cells>\n      <CellData Scalars=\"quality\">\n");
        cell_data(cells);
        out_.write("      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    }

private:
    void legend() {
        out_.write("<!-- tubemesh hybrid mesh: volume cells, then boundary faces. Cell data: dim (3 cell, "
                   "2 boundary face), kind (0 tetrahedron, 1 pyramid, 2 hexahedron, 3 triangle, 4 quad), "
                   "group (id, names below and in the field data), quality (tet collapse; pyramid and hex "
                   "scaled Jacobian; a face repeats its cell's value).\n");
        for (std::size_t g = 0; g < groups_.size(); ++g) {
            out_.write("     group ");
            out_.write_number(g);
            out_.write(groups_[g].dim == 3 ? ": region \"" : ": surface group \"");
            out_.write(comment_safe(groups_[g].name));
            out_.write("\"\n");
        }
        out_.write("-->\n");
    }

    // Opens a DataArray, lets `fill` put exactly `bytes` bytes of values, closes it.
    // `tuples` > 0 writes NumberOfTuples, which VTK needs for field data.
    template <class Fill>
    void data_array(const char* type, const std::string& name, int components, std::uint64_t bytes, Fill&& fill,
                    std::uint64_t tuples = 0) {
        out_.write("        <DataArray type=\"");
        out_.write(type);
        out_.write("\" Name=\"");
        out_.write(attribute_safe(name));
        out_.write("\"");
        if (components > 1) {
            out_.write(" NumberOfComponents=\"");
            out_.write_number(components);
            out_.write("\"");
        }
        if (tuples > 0) {
            out_.write(" NumberOfTuples=\"");
            out_.write_number(tuples);
            out_.write("\"");
        }
        out_.write(" format=\"binary\">\n          ");
        Base64Writer b(out_);
        b.put(bytes);
        fill(b);
        b.finish();
        out_.write("\n        </DataArray>\n");
    }

    void field_data() {
        if (groups_.empty()) return;
        out_.write("    <FieldData>\n");
        for (std::size_t g = 0; g < groups_.size(); ++g)
            data_array(
                "Int32", groups_[g].field_name, 1, 8,
                [&](Base64Writer& b) {
                    b.put(static_cast<std::int32_t>(g));
                    b.put(std::int32_t{groups_[g].dim});
                },
                2);
        out_.write("    </FieldData>\n");
    }

    void points() {
        const std::uint64_t n = mesh_.point_count();
        data_array("Float64", "Points", 3, 24 * n, [&](Base64Writer& b) {
            for (index_t i = 0; i < n; ++i) {
                b.put(mesh_.x[i]);
                b.put(mesh_.y[i]);
                b.put(mesh_.z[i]);
            }
        });
    }

    void cell_arrays(std::uint64_t cells, std::uint64_t connectivity) {
        data_array("Int64", "connectivity", 1, 8 * connectivity, [&](Base64Writer& b) {
            for (const Block& k : blocks_)
                for (index_t node : *k.nodes) b.put(std::int64_t{node});
        });
        data_array("Int64", "offsets", 1, 8 * cells, [&](Base64Writer& b) {
            std::int64_t end = 0;
            for (const Block& k : blocks_)
                for (std::size_t i = 0; i < k.count(); ++i) {
                    end += k.size;
                    b.put(end);
                }
        });
        each_cell_value("UInt8", "types", [](const Block& k) { return k.vtk_type; }, cells);
    }

    // One value per element of a block, the same for the whole block.
    template <class Value>
    void each_cell_value(const char* type, const char* name, Value&& value, std::uint64_t cells) {
        using T = decltype(value(blocks_[0]));
        data_array(type, name, 1, sizeof(T) * cells, [&](Base64Writer& b) {
            for (const Block& k : blocks_)
                for (std::size_t i = 0; i < k.count(); ++i) b.put(value(k));
        });
    }

    void cell_data(std::uint64_t cells) {
        each_cell_value("UInt8", "dim", [](const Block& k) { return k.dim; }, cells);
        each_cell_value("UInt8", "kind", [](const Block& k) { return k.kind; }, cells);
        data_array("UInt32", "group", 1, 4 * cells, [&](Base64Writer& b) {
            for (const Block& k : blocks_)
                for (index_t id : *k.ids) b.put(static_cast<std::uint32_t>(k.first_group + id));
        });
        data_array("Float64", "quality", 1, 8 * cells, [&](Base64Writer& b) {
            for (const Block& k : blocks_)
                for (double q : *k.quality) b.put(q);
        });
    }

    const HybridMesh& mesh_;
    const std::vector<VtuGroup> groups_;
    const Blocks blocks_;
    AtomicFile& out_;
};

}  // namespace
}  // namespace io

void write_vtu(const HybridMesh& mesh, const std::filesystem::path& path) {
    io::check_layout_for_writing(mesh, path);
    io::CellQuality quality;
    for (CellKind k : kAllCellKinds) {
        quality[static_cast<int>(k)] = cell_quality(mesh, k);
        if (quality[static_cast<int>(k)].size() != mesh.cell_count(k))
            throw Error("internal error: cell_quality gave the wrong number of values for '" + path.string() + "'");
    }
    const io::FaceQuality face_quality = io::face_quality(mesh, quality);
    io::AtomicFile out(path);
    io::VtuWriter(mesh, quality, face_quality, out).write();
    out.commit();
}

}  // namespace tubemesh
