// VTK XML writers for ParaView and meshio: .vtu (the volume cells) and .vtm (a multiblock of
// one .vtu per region and per surface group, each block named after its group).
//
// Encoding: every DataArray is format="binary" inline: one base64 stream of a UInt64 byte
// count followed by the little-endian values (header_type="UInt64", no compression). VTK and
// meshio both read this form; raw appended data would be smaller but is not valid XML, which
// trips up generic XML tools. A grid holds only the points its elements use.
//
// Cell data of volume cells:
//   kind             UInt8   0 tetrahedron, 1 pyramid, 2 hexahedron (CellKind)
//   group            UInt32  the region id (names in the field data and the comment)
//   quality          Float64 the paper's measure: tet collapse, pyramid and hex scaled Jacobian
//   scaled_jacobian  Float64 Verdict's, every kind (standard_measures.hpp)
//   min_dihedral     Float64 tets, the smallest dihedral angle in degrees (-1 for other kinds;
//                            ParaView's "Min Angle" takes the supplement at two of the six edges)
//   aspect_ratio     Float64 tets (-1 for other kinds)
//   condition        Float64 hexes (-1 for other kinds)
// Boundary faces (.vtm only): kind 3 triangle, 4 quad; group, the surface group id; quality,
// the value of the cell the face bounds (-1 if no cell has it, as in partial meshes).
// No NaN: ParaView colours NaN apart and its thresholds drop such cells, so a value that does not
// exist is kNoValue, below every measure of a cell a written mesh may hold.
// Field data: one Int32 array per group named after it, holding (id, dim) - the form meshio
// gives Gmsh physical groups. An XML comment at the top lists the same, the kinds, the length
// unit and where each surface group is. (The kind is also the VTK cell type ParaView shows.)
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/io/base64_writer.hpp"
#include "engine/io/boundary_cell_faces.hpp"
#include "engine/io/group_order.hpp"
#include "engine/io/layout_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/io/mesh_notes.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh {

namespace io {
namespace {

constexpr std::array<FaceKind, kFaceKindCount> kAllFaceKinds = {FaceKind::Tri, FaceKind::Quad};

constexpr std::uint8_t vtk_cell_type(CellKind k) {
    return k == CellKind::Tet ? 10 : k == CellKind::Pyramid ? 14 : 12;
}
constexpr std::uint8_t vtk_cell_type(FaceKind k) { return k == FaceKind::Tri ? 5 : 9; }
constexpr std::uint8_t kind_value(CellKind k) { return static_cast<std::uint8_t>(k); }
constexpr std::uint8_t kind_value(FaceKind k) {
    return static_cast<std::uint8_t>(kCellKindCount + static_cast<int>(k));
}

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

constexpr std::size_t kMeasures = 5;
constexpr std::array<const char*, kMeasures> kMeasureNames = {"quality", "scaled_jacobian", "min_dihedral",
                                                              "aspect_ratio", "condition"};
constexpr std::array<CellMeasure, kMeasures> kMeasureOf = {CellMeasure::Primary, CellMeasure::ScaledJacobian,
                                                           CellMeasure::MinDihedral, CellMeasure::AspectRatio,
                                                           CellMeasure::Condition};

constexpr double kNoValue = -1;

// Every measure of every cell, per kind in cell order.
using CellMeasures = std::array<std::array<std::vector<double>, kMeasures>, kCellKindCount>;

CellMeasures measure_cells(const HybridMesh& mesh, const std::filesystem::path& path) {
    CellMeasures m;
    for (CellKind k : kAllCellKinds)
        for (std::size_t i = 0; i < kMeasures; ++i) {
            auto& values = m[static_cast<int>(k)][i];
            values = cell_measure(mesh, k, kMeasureOf[i]);
            for (double& v : values)
                if (std::isnan(v)) v = kNoValue;
            if (values.size() != mesh.cell_count(k))
                throw Error("internal error: a quality measure gave the wrong number of values for '" + path.string() +
                            "'");
        }
    return m;
}

// One kind's part of a grid: `elements` of the mesh block, in that order.
struct GridBlock {
    const std::vector<index_t>* nodes;
    int size;  // nodes per element
    std::uint8_t vtk_type;
    std::uint8_t kind;
    const std::vector<index_t>* ids;      // group per element of the whole block
    std::vector<index_t> elements;
    std::vector<const std::vector<double>*> data;  // per cell-data array, over the whole block
};

// What one .vtu holds: blocks of elements, their cell data and the field data.
struct Grid {
    std::vector<std::string> data_names;  // Float64 cell data, one per GridBlock::data entry
    std::vector<GridBlock> blocks;
    std::vector<std::pair<std::string, std::array<std::int32_t, 2>>> fields;
    std::vector<std::string> comment;
};

GridBlock cell_block(const HybridMesh& mesh, CellKind k, std::vector<index_t> elements, const CellMeasures& m) {
    GridBlock b{&mesh.block(k).nodes, node_count(k), vtk_cell_type(k), kind_value(k), &mesh.block(k).region,
                std::move(elements), {}};
    for (const auto& values : m[static_cast<int>(k)]) b.data.push_back(&values);
    return b;
}

GridBlock face_block(const HybridMesh& mesh, FaceKind k, std::vector<index_t> elements, const std::vector<double>& quality) {
    return {&mesh.block(k).nodes, face_size(k),          vtk_cell_type(k), kind_value(k),
            &mesh.block(k).group, std::move(elements), {&quality}};
}

std::vector<index_t> all_of(std::size_t count) {
    std::vector<index_t> v(count);
    for (std::size_t i = 0; i < count; ++i) v[i] = static_cast<index_t>(i);
    return v;
}

// Field data shared by every grid: the regions and surface groups, names made distinct (VTK
// keys field arrays by name).
std::vector<std::pair<std::string, std::array<std::int32_t, 2>>> name_fields(const HybridMesh& mesh) {
    std::vector<std::pair<std::string, std::array<std::int32_t, 2>>> fields;
    std::set<std::string> taken;
    auto add = [&](const std::string& name, std::int32_t id, std::int32_t dim) {
        std::string field = name;
        for (int n = 2; !taken.insert(field).second; ++n) field = name + "_" + std::to_string(n);
        fields.push_back({field, {id, dim}});
    };
    for (std::size_t r = 0; r < mesh.region_names.size(); ++r) add(mesh.region_names[r], static_cast<std::int32_t>(r), 3);
    for (std::size_t g = 0; g < mesh.surface_group_names.size(); ++g)
        add(mesh.surface_group_names[g], static_cast<std::int32_t>(g), 2);
    return fields;
}

std::vector<std::string> comment_lines(const HybridMesh& mesh, const MeshDescription* description, const std::string& what) {
    std::vector<std::string> lines{"tubemesh hybrid mesh: " + what};
    lines.push_back("cell data: kind (0 tetrahedron, 1 pyramid, 2 hexahedron, 3 triangle, 4 quad), group (a volume cell's "
                    "region id, a boundary face's surface group id; names in the field data), quality (the paper's: tet "
                    "collapse, pyramid and hex scaled Jacobian; a face repeats its cell's), scaled_jacobian and "
                    "aspect_ratio (Verdict's), min_dihedral (the smallest dihedral angle of a tet, degrees), "
                    "condition (hexes); -1 where a kind has no such measure or a face no cell");
    for (std::size_t r = 0; r < mesh.region_names.size(); ++r)
        lines.push_back(std::string("region ") + std::to_string(r) + ": " + mesh.region_names[r]);
    for (std::size_t g = 0; g < mesh.surface_group_names.size(); ++g)
        lines.push_back(std::string("surface group ") + std::to_string(g) + ": " + mesh.surface_group_names[g]);
    for (const std::string& line : mesh_notes(mesh, description)) lines.push_back(line);
    return lines;
}

class VtuWriter {
public:
    VtuWriter(const HybridMesh& mesh, const Grid& grid, AtomicFile& out) : mesh_(mesh), grid_(grid), out_(out) {
        // Only the points the elements use, in mesh order.
        local_.assign(mesh_.point_count(), kNoIndex);
        for (const GridBlock& b : grid_.blocks)
            for (index_t e : b.elements)
                for (int k = 0; k < b.size; ++k) local_[(*b.nodes)[std::size_t{e} * b.size + k]] = 0;
        for (index_t p = 0; p < mesh_.point_count(); ++p)
            if (local_[p] == 0) {
                local_[p] = static_cast<index_t>(points_.size());
                points_.push_back(p);
            }
        for (const GridBlock& b : grid_.blocks) {
            cells_ += b.elements.size();
            connectivity_ += b.elements.size() * static_cast<std::size_t>(b.size);
        }
    }

    void write() {
        out_.write("<?xml version=\"1.0\"?>\n<!--\n");
        for (const std::string& line : grid_.comment) out_.write("  " + comment_safe(line) + "\n");
        out_.write("-->\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                   "header_type=\"UInt64\">\n  <UnstructuredGrid>\n");
        field_data();
        out_.write("    <Piece NumberOfPoints=\"");
        out_.write_number(points_.size());
        out_.write("\" NumberOfCells=\"");
        out_.write_number(cells_);
        out_.write("\">\n      <Points>\n");
        points();
        out_.write("      </Points>\n      <Cells>\n");
        cell_arrays();
        out_.write("      </Cells>\n      <CellData Scalars=\"quality\">\n");
        cell_data();
        out_.write("      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    }

private:
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
        if (grid_.fields.empty()) return;
        out_.write("    <FieldData>\n");
        // A plain pair, not a structured binding: clang 14 (the fuzz build) cannot capture those.
        for (const auto& field : grid_.fields)
            data_array(
                "Int32", field.first, 1, 8,
                [&](Base64Writer& b) {
                    b.put(field.second[0]);
                    b.put(field.second[1]);
                },
                2);
        out_.write("    </FieldData>\n");
    }

    void points() {
        data_array("Float64", "Points", 3, 24 * points_.size(), [&](Base64Writer& b) {
            for (index_t p : points_) {
                b.put(mesh_.x[p]);
                b.put(mesh_.y[p]);
                b.put(mesh_.z[p]);
            }
        });
    }

    void cell_arrays() {
        data_array("Int64", "connectivity", 1, 8 * connectivity_, [&](Base64Writer& b) {
            for (const GridBlock& k : grid_.blocks)
                for (index_t e : k.elements)
                    for (int n = 0; n < k.size; ++n)
                        b.put(std::int64_t{local_[(*k.nodes)[std::size_t{e} * k.size + n]]});
        });
        data_array("Int64", "offsets", 1, 8 * cells_, [&](Base64Writer& b) {
            std::int64_t end = 0;
            for (const GridBlock& k : grid_.blocks)
                for (std::size_t i = 0; i < k.elements.size(); ++i) {
                    end += k.size;
                    b.put(end);
                }
        });
        per_element("UInt8", "types", [](const GridBlock& k, index_t) { return k.vtk_type; });
    }

    template <class Value>
    void per_element(const char* type, const std::string& name, Value&& value) {
        using T = decltype(value(grid_.blocks[0], 0));
        data_array(type, name, 1, sizeof(T) * cells_, [&](Base64Writer& b) {
            for (const GridBlock& k : grid_.blocks)
                for (index_t e : k.elements) b.put(value(k, e));
        });
    }

    void cell_data() {
        if (grid_.blocks.empty()) return;
        per_element("UInt8", "kind", [](const GridBlock& k, index_t) { return k.kind; });
        per_element("UInt32", "group", [](const GridBlock& k, index_t e) { return static_cast<std::uint32_t>((*k.ids)[e]); });
        for (std::size_t d = 0; d < grid_.data_names.size(); ++d)
            per_element("Float64", grid_.data_names[d], [d](const GridBlock& k, index_t e) {
                return d < k.data.size() ? (*k.data[d])[e] : kNoValue;
            });
    }

    const HybridMesh& mesh_;
    const Grid& grid_;
    AtomicFile& out_;
    std::vector<index_t> local_;   // mesh point -> grid point
    std::vector<index_t> points_;  // grid point -> mesh point
    std::uint64_t cells_ = 0, connectivity_ = 0;
};

Grid volume_grid(const HybridMesh& mesh, const MeshDescription* description, const CellMeasures& m,
                 const std::array<std::vector<index_t>, kCellKindCount>& elements) {
    Grid grid;
    grid.data_names.assign(kMeasureNames.begin(), kMeasureNames.end());
    for (CellKind k : kAllCellKinds) grid.blocks.push_back(cell_block(mesh, k, elements[static_cast<int>(k)], m));
    grid.fields = name_fields(mesh);
    grid.comment = comment_lines(mesh, description, "volume cells");
    return grid;
}

// Per face kind, in face order: the primary quality of the cell that has the face.
std::array<std::vector<double>, kFaceKindCount> face_quality(const HybridMesh& mesh, const CellMeasures& m) {
    const auto owners = boundary_cell_faces(mesh);
    std::array<std::vector<double>, kFaceKindCount> q;
    for (FaceKind k : kAllFaceKinds)
        for (const CellFaceRef& ref : owners[static_cast<int>(k)])
            q[static_cast<int>(k)].push_back(ref.cell == kNoIndex ? kNoValue : m[static_cast<int>(ref.kind)][0][ref.cell]);
    return q;
}

// A file name part from a group name: letters, digits, '-', '_' and '.' kept, the rest '_'.
std::string file_part(const std::string& name) {
    std::string s = name;
    for (char& c : s)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.'))
            c = '_';
    if (s.empty() || s.front() == '.') return "g" + s;
    return s;
}

}  // namespace
}  // namespace io

void write_vtu(const HybridMesh& mesh, const std::filesystem::path& path, const MeshDescription* description) {
    io::check_layout_for_writing(mesh, path);
    const io::CellMeasures measures = io::measure_cells(mesh, path);
    std::array<std::vector<index_t>, kCellKindCount> elements;
    for (CellKind k : kAllCellKinds) elements[static_cast<int>(k)] = io::all_of(mesh.cell_count(k));
    const io::Grid grid = io::volume_grid(mesh, description, measures, elements);
    io::AtomicFile out(path);
    io::VtuWriter(mesh, grid, out).write();
    out.commit();
}

void write_vtm(const HybridMesh& mesh, const std::filesystem::path& path, const MeshDescription* description) {
    namespace fs = std::filesystem;
    io::check_layout_for_writing(mesh, path);
    const io::CellMeasures measures = io::measure_cells(mesh, path);
    const auto face_quality = io::face_quality(mesh, measures);

    // Every grid with its block name and file, regions first.
    struct Part {
        std::string block;  // "volume" or "boundary"
        std::string name;
        std::string file;   // relative to the .vtm's folder
        io::Grid grid;
    };
    std::vector<Part> parts;
    const std::string folder = path.stem().string();
    std::array<io::GroupOrder, kCellKindCount> by_region;
    for (CellKind k : kAllCellKinds)
        by_region[static_cast<int>(k)] = io::order_by_group(mesh.block(k).region, mesh.region_names.size());
    for (std::size_t r = 0; r < mesh.region_names.size(); ++r) {
        std::array<std::vector<index_t>, kCellKindCount> elements;
        bool any = false;
        for (CellKind k : kAllCellKinds) {
            const auto cells = by_region[static_cast<int>(k)].group(r);
            elements[static_cast<int>(k)].assign(cells.begin(), cells.end());
            any = any || !cells.empty();
        }
        if (!any) continue;
        io::Grid grid = io::volume_grid(mesh, description, measures, elements);
        grid.comment.front() = "tubemesh hybrid mesh: region " + mesh.region_names[r];
        parts.push_back({"volume", mesh.region_names[r],
                         folder + "/volume_" + io::file_part(mesh.region_names[r]) + ".vtu", std::move(grid)});
    }
    std::array<io::GroupOrder, kFaceKindCount> by_group;
    for (FaceKind k : io::kAllFaceKinds)
        by_group[static_cast<int>(k)] = io::order_by_group(mesh.block(k).group, mesh.surface_group_names.size());
    for (std::size_t g = 0; g < mesh.surface_group_names.size(); ++g) {
        io::Grid grid;
        grid.data_names = {"quality"};
        bool any = false;
        for (FaceKind k : io::kAllFaceKinds) {
            const auto faces = by_group[static_cast<int>(k)].group(g);
            grid.blocks.push_back(io::face_block(mesh, k, {faces.begin(), faces.end()}, face_quality[static_cast<int>(k)]));
            any = any || !faces.empty();
        }
        if (!any) continue;
        grid.fields = io::name_fields(mesh);
        grid.comment = io::comment_lines(mesh, description, "surface group " + mesh.surface_group_names[g]);
        const std::string role = io::group_role(mesh, description, g);
        parts.push_back({"boundary", mesh.surface_group_names[g] + (role.empty() ? "" : " (" + role + ")"),
                         folder + "/boundary_" + io::file_part(mesh.surface_group_names[g]) + ".vtu", std::move(grid)});
    }

    // The folder beside the .vtm; removed again if this call made it and fails or is interrupted.
    const fs::path dir = path.parent_path() / folder;
    // Tracked before it is made, so that an interrupt right after finds it (removed only if empty).
    io::TrackedTemporary tracked_dir(dir, io::TemporaryKind::Folder);
    std::error_code ec;
    const bool made = fs::create_directory(dir, ec);
    if (!made) tracked_dir.release();
    if (ec || !fs::is_directory(dir))
        throw Error("cannot write '" + path.string() + "': cannot create the folder '" + dir.string() + "' for its blocks" +
                    (ec ? ": " + ec.message() : std::string(": a file of that name is in the way")));
    if (made) io::CommitGroup::folder_made(dir);
    // What a killed run left there, and the .vtu files of an earlier .vtm this one does not list.
    io::remove_dead_temporaries(dir);
    std::vector<fs::path> earlier_parts;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const fs::path& p = it->path();
        const bool ours = std::any_of(parts.begin(), parts.end(), [&](const Part& part) {
            return fs::path(part.file).filename() == p.filename();
        });
        std::error_code kind;
        if (!ours && p.extension() == ".vtu" && p.filename().native().front() != '.' && it->is_regular_file(kind))
            earlier_parts.push_back(p);
    }
    try {
        // Every block complete under a temporary name before any is renamed into place.
        std::vector<std::unique_ptr<io::AtomicFile>> files;
        for (const Part& p : parts) {
            files.push_back(std::make_unique<io::AtomicFile>(path.parent_path() / p.file));
            io::VtuWriter(mesh, p.grid, *files.back()).write();
        }
        io::AtomicFile index(path);
        index.write("<?xml version=\"1.0\"?>\n<!--\n  tubemesh hybrid mesh: a block per region and per surface group\n");
        for (const std::string& line : io::mesh_notes(mesh, description)) index.write("  " + io::comment_safe(line) + "\n");
        index.write("-->\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <vtkMultiBlockDataSet>\n");
        int block = 0;
        for (const char* name : {"volume", "boundary"}) {
            index.write("    <Block index=\"" + std::to_string(block++) + "\" name=\"" + name + "\">\n");
            int set = 0;
            for (const Part& p : parts)
                if (p.block == name)
                    index.write("      <DataSet index=\"" + std::to_string(set++) + "\" name=\"" +
                                io::attribute_safe(p.name) + "\" file=\"" + io::attribute_safe(p.file) + "\"/>\n");
            index.write("    </Block>\n");
        }
        index.write("  </vtkMultiBlockDataSet>\n</VTKFile>\n");
        for (auto& f : files) f->commit();
        index.commit();
        // The folder holds this .vtm's parts only: an earlier model's other parts go once the
        // new files are in place.
        for (const fs::path& stale : earlier_parts) io::CommitGroup::retire(stale);
    } catch (...) {
        if (made) fs::remove_all(dir, ec);
        throw;
    }
}

}  // namespace tubemesh
