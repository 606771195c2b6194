// Gmsh MSH 4.1 reader, ASCII and binary. Parses sections into MshContents; assemble_msh()
// builds the mesh. Files Gmsh writes are read too: nodes in many entity blocks, parametric
// coordinates, sparse tags, sections tubemesh does not use ($Periodic, $NodeData, ...).
#include "engine/io/msh_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>

#include "engine/io/file_bytes.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/io/msh_contents.hpp"
#include "engine/io/msh_cursor.hpp"
#include "engine/io/node_tag_map.hpp"

namespace tubemesh {

namespace io {
namespace {

class MshParser {
public:
    MshParser(std::string_view bytes, const std::string& name) : in_(bytes, name) {}

    MshContents parse() {
        mesh_format();
        while (!in_.at_end()) section(in_.token("a section name"));
        if (!nodes_) in_.fail("the file has no $Nodes section");
        if (!elements_seen_) in_.fail("the file has no $Elements section");
        return std::move(out_);
    }

private:
    // Smallest size of one item in binary files, for MshCursor::check_count.
    std::size_t size_bytes() const { return static_cast<std::size_t>(size_width_); }

    void mesh_format() {
        if (in_.at_end()) in_.fail("the file is empty");
        const std::string_view first = in_.token("$MeshFormat");
        if (first != "$MeshFormat") in_.fail("not a Gmsh MSH file: it does not start with $MeshFormat");
        const std::string_view version = in_.token("the MSH version");
        if (version != "4.1")
            in_.fail("MSH version " + std::string(version.substr(0, 16)) +
                     " is not supported: tubemesh reads MSH 4.1 (in Gmsh: File > Export, or -format msh41)");
        const int file_type = in_.text_int("the file type");
        if (file_type != 0 && file_type != 1) in_.fail("file type must be 0 (ASCII) or 1 (binary)");
        size_width_ = in_.text_int("the data size");
        if (size_width_ != 4 && size_width_ != 8) in_.fail("data size must be 4 or 8");
        if (file_type == 1) binary_header();
        in_.expect("$EndMeshFormat");
    }

    void binary_header() {
        in_.end_of_line();
        in_.use_binary(size_width_);
        const int one = in_.int_value("the byte order mark");
        if (one == 0x01000000) in_.fail("big-endian binary MSH files are not supported");
        if (one != 1) in_.fail("corrupt byte order mark (expected the integer 1)");
    }

    void section(std::string_view name) {
        if (name == "$PhysicalNames")
            physical_names();
        else if (name == "$Entities")
            entities();
        else if (name == "$Nodes")
            nodes();
        else if (name == "$Elements")
            elements();
        else if (name.size() > 1 && name.front() == '$' && name.substr(0, 4) != "$End")
            in_.skip_section(name.substr(1));  // $Periodic, $NodeData, $PartitionedEntities, ...
        else
            in_.fail("expected a section such as $Nodes, found \"" + std::string(name.substr(0, 40)) + "\"");
    }

    // In binary files the values start right after the section's line.
    void section_body() {
        if (in_.binary()) in_.end_of_line();
    }

    void physical_names() {
        const std::uint64_t count = in_.text_size("the number of physical names");
        in_.check_count(count, 5, "physical name");
        for (std::uint64_t i = 0; i < count; ++i) {
            const int dim = in_.text_int("a physical group dimension");
            const int tag = in_.text_int("a physical tag");
            out_.physical_names.push_back({dim, tag, in_.quoted("a physical name")});
        }
        in_.expect("$EndPhysicalNames");
    }

    void entities() {
        section_body();
        std::array<std::uint64_t, 4> count{};
        for (std::uint64_t& c : count) c = in_.size_value("an entity count");
        for (int dim = 0; dim < 4; ++dim) {
            // tag, coordinates or box, physical count, bounding count
            const std::size_t smallest = 4 + (dim == 0 ? 24 : 48) + size_bytes() * (dim == 0 ? 1 : 2);
            in_.check_count(count[dim], smallest, "entity");
            for (std::uint64_t i = 0; i < count[dim]; ++i) entity(dim);
        }
        in_.expect("$EndEntities");
    }

    void entity(int dim) {
        MshEntity e{dim, in_.int_value("an entity tag"), std::nullopt};
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) in_.double_value("an entity coordinate");
        const std::uint64_t physicals = in_.size_value("a physical tag count");
        in_.check_count(physicals, 4, "physical tag");
        for (std::uint64_t k = 0; k < physicals; ++k) {
            const int tag = in_.int_value("a physical tag");
            if (k == 0) e.physical = tag;
        }
        if (dim > 0) {
            const std::uint64_t bounding = in_.size_value("a bounding entity count");
            in_.check_count(bounding, 4, "bounding entity");
            for (std::uint64_t k = 0; k < bounding; ++k) in_.int_value("a bounding entity tag");
        }
        if (dim >= 2) out_.entities.push_back(e);
    }

    void nodes() {
        if (nodes_) in_.fail("a second $Nodes section");
        section_body();
        const std::uint64_t block_count = in_.size_value("the number of node blocks");
        const std::uint64_t count = in_.size_value("the number of nodes");
        in_.size_value("the smallest node tag");
        in_.size_value("the largest node tag");
        in_.check_count(block_count, 12 + size_bytes(), "node block");
        in_.check_count(count, size_bytes() + 24, "node");
        if (count >= kNoIndex) in_.fail("too many nodes for tubemesh (" + std::to_string(count) + ")");

        std::vector<std::uint64_t> tags;
        tags.reserve(count);
        std::vector<double> xyz;
        xyz.reserve(3 * count);
        for (std::uint64_t b = 0; b < block_count; ++b) node_block(count, tags, xyz);
        if (tags.size() != count)
            in_.fail("$Nodes announces " + std::to_string(count) + " nodes but its blocks hold " +
                     std::to_string(tags.size()));
        in_.expect("$EndNodes");
        sort_nodes(tags, xyz);
    }

    void node_block(std::uint64_t announced, std::vector<std::uint64_t>& tags, std::vector<double>& xyz) {
        const int dim = in_.int_value("an entity dimension");
        if (dim < 0 || dim > 3) in_.fail("entity dimension " + std::to_string(dim) + " is not 0, 1, 2 or 3");
        in_.int_value("an entity tag");
        const int parametric = in_.int_value("the parametric flag");
        if (parametric != 0 && parametric != 1) in_.fail("the parametric flag must be 0 or 1");
        const std::uint64_t n = in_.size_value("the number of nodes in a block");
        if (n > announced - tags.size()) in_.fail("a node block holds more nodes than $Nodes announces");
        // Parametric nodes carry u (curves), u v (surfaces) or u v w (volumes) after x y z.
        const int extra = parametric ? dim : 0;
        for (std::uint64_t i = 0; i < n; ++i) {
            const std::uint64_t tag = in_.size_value("a node tag");
            if (tag == 0) in_.fail("node tag 0 (tags start at 1)");
            tags.push_back(tag);
        }
        for (std::uint64_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) {
                xyz.push_back(in_.double_value("a node coordinate"));
                // Otherwise a NaN reaches the check as a "non-positive volume".
                if (!std::isfinite(xyz.back())) in_.fail("node " + std::to_string(tags[tags.size() - n + i]) +
                                                         " has a coordinate that is not a finite number");
            }
            for (int k = 0; k < extra; ++k) in_.double_value("a parametric coordinate");
        }
    }

    // Points are numbered in ascending tag order: tubemesh's own files use tags 1..n.
    void sort_nodes(std::vector<std::uint64_t>& tags, const std::vector<double>& xyz) {
        std::vector<index_t> order(tags.size());
        std::iota(order.begin(), order.end(), index_t{0});
        std::sort(order.begin(), order.end(), [&](index_t a, index_t b) { return tags[a] < tags[b]; });
        std::vector<std::uint64_t> sorted(tags.size());
        out_.x.resize(tags.size());
        out_.y.resize(tags.size());
        out_.z.resize(tags.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            sorted[i] = tags[order[i]];
            if (i > 0 && sorted[i] == sorted[i - 1])
                in_.fail("node tag " + std::to_string(sorted[i]) + " appears twice in the $Nodes section ending here");
            out_.x[i] = xyz[3 * std::size_t{order[i]}];
            out_.y[i] = xyz[3 * std::size_t{order[i]} + 1];
            out_.z[i] = xyz[3 * std::size_t{order[i]} + 2];
        }
        nodes_ = std::make_unique<NodeTagMap>(std::move(sorted));
    }

    void elements() {
        if (!nodes_) in_.fail("$Elements comes before $Nodes");
        if (elements_seen_) in_.fail("a second $Elements section");
        elements_seen_ = true;
        section_body();
        const std::uint64_t block_count = in_.size_value("the number of element blocks");
        const std::uint64_t count = in_.size_value("the number of elements");
        in_.size_value("the smallest element tag");
        in_.size_value("the largest element tag");
        in_.check_count(block_count, 12 + size_bytes(), "element block");
        in_.check_count(count, 2 * size_bytes(), "element");
        std::uint64_t read = 0;
        for (std::uint64_t b = 0; b < block_count; ++b) read += element_block(count - read);
        if (read != count)
            in_.fail("$Elements announces " + std::to_string(count) + " elements but its blocks hold " +
                     std::to_string(read));
        in_.expect("$EndElements");
        for (MshElements& e : out_.elements) order_by_tag(e);
    }

    // Ascending tags give tubemesh's mesh order back; a repeated tag is corruption.
    void order_by_tag(MshElements& e) {
        e.order.resize(e.tag.size());
        std::iota(e.order.begin(), e.order.end(), index_t{0});
        std::sort(e.order.begin(), e.order.end(), [&](index_t a, index_t b) { return e.tag[a] < e.tag[b]; });
        for (std::size_t i = 1; i < e.order.size(); ++i)
            if (e.tag[e.order[i]] == e.tag[e.order[i - 1]])
                in_.fail("element tag " + std::to_string(e.tag[e.order[i]]) +
                         " appears twice in the $Elements section ending here");
    }

    // Returns the number of elements read.
    std::uint64_t element_block(std::uint64_t left) {
        const int dim = in_.int_value("an entity dimension");
        const int entity = in_.int_value("an entity tag");
        const int type = in_.int_value("an element type");
        const std::optional<MshKind> kind = msh_kind_of_type(type);
        if (!kind)
            in_.fail("element type " + std::to_string(type) + " (" + std::string(msh_type_name(type)) +
                     ") is not supported: tubemesh reads 4-node tetrahedra (type 4), 5-node pyramids (7), "
                     "8-node hexahedra (5), 3-node triangles (2) and 4-node quadrangles (3)");
        if (dim != kind->dimension)
            in_.fail("element type " + std::to_string(type) + " in a block of dimension " + std::to_string(dim));
        const std::uint64_t n = in_.size_value("the number of elements in a block");
        if (n > left) in_.fail("an element block holds more elements than $Elements announces");
        in_.check_count(n, (1 + static_cast<std::size_t>(kind->node_count)) * size_bytes(), "element");

        const auto block = static_cast<index_t>(out_.blocks.size());
        out_.blocks.push_back({dim, entity});
        MshElements& e = out_.elements[kind->index];
        for (std::uint64_t i = 0; i < n; ++i) {
            const std::uint64_t tag = in_.size_value("an element tag");
            e.tag.push_back(tag);
            e.block.push_back(block);
            for (int k = 0; k < kind->node_count; ++k) {
                const std::uint64_t node_tag = in_.size_value("a node tag");
                const index_t point = nodes_->find(node_tag);
                if (point == kNoIndex)
                    in_.fail("element " + std::to_string(tag) + " refers to node tag " + std::to_string(node_tag) +
                             ", which $Nodes does not define");
                e.nodes.push_back(point);
            }
        }
        return n;
    }

    MshCursor in_;
    MshContents out_;
    int size_width_ = 8;
    std::unique_ptr<NodeTagMap> nodes_;  // set by $Nodes
    bool elements_seen_ = false;
};

}  // namespace

HybridMesh read_msh_bytes(std::string_view bytes, const std::string& name) {
    return assemble_msh(MshParser(bytes, name).parse());
}

}  // namespace io

HybridMesh read_msh(const std::filesystem::path& path) {
    const std::string bytes = io::read_file_bytes(path);
    return io::read_msh_bytes(bytes, path.string());
}

}  // namespace tubemesh
