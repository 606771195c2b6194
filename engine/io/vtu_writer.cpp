// VTK XML UnstructuredGrid (.vtu) writer for ParaView and meshio.
//
// Encoding: every DataArray is format="binary" inline: one base64 stream of a UInt64 byte
// count followed by the little-endian values (header_type="UInt64", no compression). VTK and
// meshio both read this form; raw appended data would be smaller but is not valid XML, which
// trips up generic XML tools.
//
// Content: volume cells only (tets, pyramids, hexes, in that order and each kind in mesh
// order); boundary faces are left out because ParaView users want the volume, and the
// surface groups live in the .msh and .inp files. Cell data:
//   kind     UInt8   0 tetrahedron, 1 pyramid, 2 hexahedron (CellKind)
//   region   UInt32  region id; an XML comment at the top lists the names
//   quality  Float64 the primary measure: tet collapse, pyramid / hex scaled Jacobian
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/io/base64_writer.hpp"
#include "engine/io/layout_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh {

namespace io {
namespace {

constexpr std::uint8_t vtk_cell_type(CellKind k) {
    return k == CellKind::Tet ? 10 : k == CellKind::Pyramid ? 14 : 12;
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

class VtuWriter {
public:
    VtuWriter(const HybridMesh& mesh, const std::array<std::vector<double>, kCellKindCount>& quality, AtomicFile& out)
        : mesh_(mesh), quality_(quality), out_(out) {}

    void write() {
        std::uint64_t cells = 0, connectivity = 0;
        for (CellKind k : kAllCellKinds) {
            cells += mesh_.cell_count(k);
            connectivity += mesh_.block(k).nodes.size();
        }
        out_.write("<?xml version=\"1.0\"?>\n");
        legend();
        out_.write("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                   "header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"");
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
        out_.write("<!-- tubemesh hybrid mesh. Cell data: kind (0 tetrahedron, 1 pyramid, 2 hexahedron), "
                   "region (id, names below), quality (tet collapse; pyramid and hex scaled Jacobian).\n");
        for (std::size_t r = 0; r < mesh_.region_names.size(); ++r) {
            out_.write("     region ");
            out_.write_number(r);
            out_.write(": \"");
            out_.write(comment_safe(mesh_.region_names[r]));
            out_.write("\"\n");
        }
        out_.write("-->\n");
    }

    // Opens a DataArray, lets `fill` put exactly `bytes` bytes of values, closes it.
    template <class Fill>
    void data_array(const char* type, const char* name, int components, std::uint64_t bytes, Fill&& fill) {
        out_.write("        <DataArray type=\"");
        out_.write(type);
        out_.write("\" Name=\"");
        out_.write(name);
        out_.write("\"");
        if (components > 1) {
            out_.write(" NumberOfComponents=\"");
            out_.write_number(components);
            out_.write("\"");
        }
        out_.write(" format=\"binary\">\n          ");
        Base64Writer b(out_);
        b.put(bytes);
        fill(b);
        b.finish();
        out_.write("\n        </DataArray>\n");
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
            for (CellKind k : kAllCellKinds)
                for (index_t node : mesh_.block(k).nodes) b.put(std::int64_t{node});
        });
        data_array("Int64", "offsets", 1, 8 * cells, [&](Base64Writer& b) {
            std::int64_t end = 0;
            for (CellKind k : kAllCellKinds)
                for (index_t i = 0; i < mesh_.cell_count(k); ++i) {
                    end += node_count(k);
                    b.put(end);
                }
        });
        data_array("UInt8", "types", 1, cells, [&](Base64Writer& b) {
            for (CellKind k : kAllCellKinds)
                for (index_t i = 0; i < mesh_.cell_count(k); ++i) b.put(vtk_cell_type(k));
        });
    }

    void cell_data(std::uint64_t cells) {
        data_array("UInt8", "kind", 1, cells, [&](Base64Writer& b) {
            for (CellKind k : kAllCellKinds)
                for (index_t i = 0; i < mesh_.cell_count(k); ++i) b.put(static_cast<std::uint8_t>(k));
        });
        data_array("UInt32", "region", 1, 4 * cells, [&](Base64Writer& b) {
            for (CellKind k : kAllCellKinds)
                for (index_t r : mesh_.block(k).region) b.put(r);
        });
        data_array("Float64", "quality", 1, 8 * cells, [&](Base64Writer& b) {
            for (CellKind k : kAllCellKinds)
                for (double q : quality_[static_cast<int>(k)]) b.put(q);
        });
    }

    const HybridMesh& mesh_;
    const std::array<std::vector<double>, kCellKindCount>& quality_;
    AtomicFile& out_;
};

}  // namespace
}  // namespace io

void write_vtu(const HybridMesh& mesh, const std::filesystem::path& path) {
    io::check_layout_for_writing(mesh, path);
    std::array<std::vector<double>, kCellKindCount> quality;
    for (CellKind k : kAllCellKinds) {
        quality[static_cast<int>(k)] = cell_quality(mesh, k);
        if (quality[static_cast<int>(k)].size() != mesh.cell_count(k))
            throw Error("internal error: cell_quality gave the wrong number of values for '" + path.string() + "'");
    }
    io::AtomicFile out(path);
    io::VtuWriter(mesh, quality, out).write();
    out.commit();
}

}  // namespace tubemesh
