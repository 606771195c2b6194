#include "bench/peer_mesh_files.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include "engine/io/file_bytes.hpp"

namespace tubemesh::bench {

namespace fs = std::filesystem;

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File open_for_writing(const fs::path& path) {
    File f(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!f) throw Error("cannot write " + path.string());
    return f;
}

// Whitespace-separated numbers of TetGen's text files; '#' starts a comment to the line's end.
class NumberCursor {
public:
    NumberCursor(std::string text, std::string name) : text_(std::move(text)), name_(std::move(name)) {}

    double next() {
        skip();
        const char* begin = text_.c_str() + pos_;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin) throw Error(name_ + ": a number is missing at byte " + std::to_string(pos_));
        pos_ += static_cast<std::size_t>(end - begin);
        return v;
    }
    long next_int() { return static_cast<long>(next()); }
    void skip_line() {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    }

private:
    void skip() {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '#') skip_line();
            else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') ++pos_;
            else return;
        }
    }
    std::string text_, name_;
    std::size_t pos_ = 0;
};

}  // namespace

ClosedFront compact_front(const HybridMesh& mesh, std::span<const index_t> front) {
    ClosedFront out;
    std::vector<index_t> id(mesh.point_count(), kNoIndex);
    out.triangles.reserve(front.size());
    for (index_t v : front) {
        if (id[v] == kNoIndex) {
            id[v] = static_cast<index_t>(out.xyz.size() / 3);
            out.xyz.insert(out.xyz.end(), {mesh.x[v], mesh.y[v], mesh.z[v]});
        }
        out.triangles.push_back(id[v]);
    }
    return out;
}

void write_smesh(const ClosedFront& front, const fs::path& path) {
    const File f = open_for_writing(path);
    const std::size_t points = front.xyz.size() / 3, triangles = front.triangles.size() / 3;
    std::fprintf(f.get(), "%zu 3 0 0\n", points);
    for (std::size_t i = 0; i < points; ++i)
        std::fprintf(f.get(), "%zu %.17g %.17g %.17g\n", i + 1, front.xyz[3 * i], front.xyz[3 * i + 1],
                     front.xyz[3 * i + 2]);
    std::fprintf(f.get(), "%zu 0\n", triangles);
    for (std::size_t t = 0; t < triangles; ++t)
        std::fprintf(f.get(), "3 %u %u %u\n", front.triangles[3 * t] + 1, front.triangles[3 * t + 1] + 1,
                     front.triangles[3 * t + 2] + 1);
    std::fprintf(f.get(), "0\n0\n");  // holes, regions
    if (std::ferror(f.get())) throw Error("cannot write " + path.string());
}

void write_msh22_surface(const ClosedFront& front, const fs::path& path) {
    const File f = open_for_writing(path);
    const std::size_t points = front.xyz.size() / 3, triangles = front.triangles.size() / 3;
    std::fprintf(f.get(), "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%zu\n", points);
    for (std::size_t i = 0; i < points; ++i)
        std::fprintf(f.get(), "%zu %.17g %.17g %.17g\n", i + 1, front.xyz[3 * i], front.xyz[3 * i + 1],
                     front.xyz[3 * i + 2]);
    std::fprintf(f.get(), "$EndNodes\n$Elements\n%zu\n", triangles);
    // Type 2 (3-node triangle), two tags: physical 0 (none), elementary 1.
    for (std::size_t t = 0; t < triangles; ++t)
        std::fprintf(f.get(), "%zu 2 2 0 1 %u %u %u\n", t + 1, front.triangles[3 * t] + 1,
                     front.triangles[3 * t + 1] + 1, front.triangles[3 * t + 2] + 1);
    std::fprintf(f.get(), "$EndElements\n");
    if (std::ferror(f.get())) throw Error("cannot write " + path.string());
}

HybridMesh read_tetgen_mesh(const fs::path& node_file, const fs::path& ele_file) {
    HybridMesh mesh;
    NumberCursor nodes(io::read_file_bytes(node_file), node_file.string());
    const long points = nodes.next_int();
    nodes.skip_line();  // dimension, attribute count, marker flag
    long first = 0;
    mesh.x.reserve(static_cast<std::size_t>(points));
    mesh.y.reserve(static_cast<std::size_t>(points));
    mesh.z.reserve(static_cast<std::size_t>(points));
    for (long i = 0; i < points; ++i) {
        const long index = nodes.next_int();
        if (i == 0) first = index;
        const double x = nodes.next(), y = nodes.next(), z = nodes.next();
        mesh.add_point(x, y, z);
        nodes.skip_line();  // attributes and marker
    }

    NumberCursor ele(io::read_file_bytes(ele_file), ele_file.string());
    const long tets = ele.next_int();
    const long corners = ele.next_int();
    if (corners != 4) throw Error(ele_file.string() + ": " + std::to_string(corners) + " nodes per tet, expected 4");
    ele.skip_line();
    const index_t region = mesh.region_id("tets");
    CellBlock& block = mesh.block(CellKind::Tet);
    block.nodes.reserve(4 * static_cast<std::size_t>(tets));
    block.region.assign(static_cast<std::size_t>(tets), region);
    for (long t = 0; t < tets; ++t) {
        ele.next_int();  // the tet's own index
        for (int k = 0; k < 4; ++k) {
            const long v = ele.next_int() - first;
            if (v < 0 || v >= points) throw Error(ele_file.string() + ": node index out of range in tet " + std::to_string(t));
            block.nodes.push_back(static_cast<index_t>(v));
        }
        ele.skip_line();
    }
    return mesh;
}

}  // namespace tubemesh::bench
