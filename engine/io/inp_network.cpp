#include "engine/io/inp_network.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "engine/io/abaqus_faces.hpp"
#include "engine/io/abaqus_number.hpp"

namespace tubemesh::io {

std::filesystem::path films_path(const std::filesystem::path& inp) {
    std::filesystem::path p = inp;
    p.replace_extension(".films" + inp.extension().string());
    return p;
}

namespace {

// One pipe's network in flow order: the stations of its nodes and, per hex layer between two
// stations (counted from the first end), the temperature node its wall faces give heat to.
struct PipeNetwork {
    std::vector<index_t> node_station;  // m_in, T_0, m_0, T_1, ..., T_last, m_out (as the labels go)
    std::vector<std::size_t> sink_of_layer;
};

PipeNetwork lay_out(std::size_t stations, bool reversed) {
    const std::size_t layers = stations - 1;
    const std::size_t segments = std::max<std::size_t>(1, layers / kStationsPerSegment);
    const auto station = [&](std::size_t flow) { return static_cast<index_t>(reversed ? layers - flow : flow); };
    PipeNetwork n;
    n.node_station.push_back(station(0));
    n.node_station.push_back(station(0));
    n.sink_of_layer.resize(layers);
    for (std::size_t j = 0; j < segments; ++j) {
        const std::size_t from = j * layers / segments, to = (j + 1) * layers / segments;
        n.node_station.push_back(station((from + to) / 2));
        n.node_station.push_back(station(to));
        for (std::size_t f = from; f < to; ++f) n.sink_of_layer[reversed ? layers - 1 - f : f] = 2 * j + 3;
    }
    n.node_station.push_back(station(layers));
    return n;
}

class NetworkWriter {
public:
    NetworkWriter(const HybridMesh& mesh, const std::array<std::vector<CellFaceRef>, kFaceKindCount>& owners,
                  const WriteOptions& options, InpNumbering numbering, AtomicFile& inp, AtomicFile& films)
        : mesh_(mesh), owners_(owners), options_(options), numbering_(numbering), inp_(inp), films_(films) {}

    void write() {
        const MeshDescription* d = options_.description;
        if (!d)
            throw Error("cannot write the pipe network to '" + inp_.target().string() +
                        "': the mesh's pipe stations are not known (a mesh read from a file does not keep them)");
        for (int k : options_.pipe_network.reverse_flow)
            if (std::none_of(d->pipes.begin(), d->pipes.end(), [&](const PipeStations& p) { return is_pipe(p, k); }))
                throw Error("--reverse-flow " + std::to_string(k) + ": the mesh has no pipe_" + std::to_string(k) +
                            (d->pipes.empty() ? std::string(" (it has no pipes)")
                                              : " (its pipes are pipe_1 to pipe_" + std::to_string(d->pipes.size()) + ")"));
        films_.write("** tubemesh: forced convection from every pipe wall face to its water (network in " +
                     inp_.target().filename().string() + "),\n** one line per face: element, F<s>FC, water node, h. "
                     "*INCLUDE it inside a heat-transfer *STEP.\n");
        // A solid without pipes (a dam's foundation block) has no water: the file holds no *FILM.
        films_.write(d->pipes.empty() ? "** the mesh has no pipes\n" : "*FILM\n");
        const std::uint64_t first_node = numbering_.nodes + 1, first_element = numbering_.elements + 1;
        for (const PipeStations& pipe : d->pipes) write_pipe(pipe);
        if (numbering_.nodes + 1 == first_node) return;
        inp_.write("*ELSET, ELSET=" + numbering_.element_sets.label("WATER") + ", GENERATE\n");
        range(first_element, numbering_.elements);
        inp_.write("*NSET, NSET=" + numbering_.node_sets.label("WATER") + ", GENERATE\n");
        range(first_node, numbering_.nodes);
    }

private:
    static bool is_pipe(const PipeStations& p, int k) { return p.name == "pipe_" + std::to_string(k); }

    bool reversed(const PipeStations& p) const {
        const auto& r = options_.pipe_network.reverse_flow;
        return std::any_of(r.begin(), r.end(), [&](int k) { return is_pipe(p, k); });
    }

    void number(double v) {
        char text[32];
        inp_.write(", ");
        inp_.write_bytes(text, abaqus_number(v, numbering_.zero_below, text));
    }

    void range(std::uint64_t first, std::uint64_t last) {
        inp_.write_number(first);
        inp_.write(", ");
        inp_.write_number(last);
        inp_.write(", 1\n");
    }

    void node_set(const std::string& name, const std::vector<std::uint64_t>& labels) {
        inp_.write("*NSET, NSET=" + numbering_.node_sets.label(name) + "\n");
        for (std::size_t i = 0; i < labels.size(); ++i) {
            inp_.write_number(labels[i]);
            inp_.write(i + 1 == labels.size() || i % 16 == 15 ? "\n" : ", ");
        }
    }

    void write_pipe(const PipeStations& pipe) {
        const std::size_t stations = pipe.centres.size();
        if (stations < 2 || pipe.wall_nodes.size() != stations * pipe.circumferential)
            throw Error("cannot write the water network of " + pipe.name + ": its stations are incomplete");
        const PipeNetwork net = lay_out(stations, reversed(pipe));
        const std::uint64_t base = numbering_.nodes + 1;  // label of node i of the network: base + i
        const std::string water = pipe.name + "_water";
        inp_.write("** " + water + ": the water in " + pipe.name + (reversed(pipe) ? ", entering at its second end" : "") +
                   "\n*NODE\n");
        for (std::size_t i = 0; i < net.node_station.size(); ++i) {
            inp_.write_number(base + i);
            const Vec3& c = pipe.centres[net.node_station[i]];
            for (double v : {c.x, c.y, c.z}) number(v);
            inp_.write("\n");
        }
        const std::size_t last = net.node_station.size() - 1;
        inp_.write("*ELEMENT, TYPE=D, ELSET=" + numbering_.element_sets.label(water) + "\n");
        std::uint64_t element = numbering_.elements + 1;
        const auto d_element = [&](std::uint64_t a, std::uint64_t m, std::uint64_t b) {
            inp_.write_number(element++);
            for (std::uint64_t v : {a, m, b}) {
                inp_.write(", ");
                inp_.write_number(v);
            }
            inp_.write("\n");
        };
        d_element(0, base, base + 1);
        for (std::size_t t = 1; t + 2 < last; t += 2) d_element(base + t, base + t + 1, base + t + 2);
        d_element(base + last - 1, base + last, 0);
        std::vector<std::uint64_t> all, flow;
        for (std::size_t i = 0; i <= last; ++i) {
            all.push_back(base + i);
            if (i % 2 == 0) flow.push_back(base + i);
        }
        node_set(water, all);
        node_set(water + "_in", {base + 1});
        node_set(water + "_out", {base + last - 1});
        node_set(water + "_flow", flow);
        films(pipe, net, base);
        numbering_.nodes += net.node_station.size();
        numbering_.elements = element - 1;
    }

    // One *FILM line per wall face of the pipe, to the water node downstream of its layer.
    void films(const PipeStations& pipe, const PipeNetwork& net, std::uint64_t base) {
        std::unordered_map<index_t, index_t> station_of;
        for (std::size_t v = 0; v < pipe.wall_nodes.size(); ++v)
            station_of.emplace(pipe.wall_nodes[v], static_cast<index_t>(v / pipe.circumferential));
        const auto group = std::find(mesh_.surface_group_names.begin(), mesh_.surface_group_names.end(), pipe.name);
        const index_t g = static_cast<index_t>(group - mesh_.surface_group_names.begin());
        const bool collapsed = options_.inp_pyramid == InpPyramid::CollapsedHex;
        char h[32];
        const std::size_t h_length = abaqus_number(options_.pipe_network.film_coefficient, 0, h);
        for (FaceKind k : {FaceKind::Tri, FaceKind::Quad}) {
            const FaceBlock& faces = mesh_.block(k);
            for (std::size_t f = 0; f < faces.group.size(); ++f) {
                if (faces.group[f] != g) continue;
                index_t low = kNoIndex, high = 0;
                bool on_stations = true;
                for (index_t v : mesh_.face(k, static_cast<index_t>(f))) {
                    const auto it = station_of.find(v);
                    on_stations = on_stations && it != station_of.end();
                    if (!on_stations) break;
                    low = std::min(low, it->second);
                    high = std::max(high, it->second);
                }
                if (!on_stations || high != low + 1)
                    throw Error("cannot write the water network of " + pipe.name + ": wall face " + std::to_string(f) +
                                " does not lie between two stations of the sweep");
                const CellFaceRef& ref = owners_[static_cast<int>(k)][f];
                films_.write_number(cell_label(ref.kind, ref.cell));
                films_.write(", F");
                films_.write_number(abaqus_face_number(ref.kind, ref.local_face, collapsed));
                films_.write("FC, ");
                films_.write_number(base + net.sink_of_layer[low]);
                films_.write(", ");
                films_.write_bytes(h, h_length);
                films_.write("\n");
            }
        }
    }

    std::uint64_t cell_label(CellKind kind, index_t cell) const {
        std::uint64_t first = 1;
        for (CellKind k : kAllCellKinds) {
            if (k == kind) break;
            first += mesh_.cell_count(k);
        }
        return first + cell;
    }

    const HybridMesh& mesh_;
    const std::array<std::vector<CellFaceRef>, kFaceKindCount>& owners_;
    const WriteOptions& options_;
    InpNumbering numbering_;
    AtomicFile& inp_;
    AtomicFile& films_;
};

}  // namespace

void write_pipe_networks(const HybridMesh& mesh, const std::array<std::vector<CellFaceRef>, kFaceKindCount>& owners,
                         const WriteOptions& options, InpNumbering numbering, AtomicFile& inp, AtomicFile& films) {
    NetworkWriter(mesh, owners, options, numbering, inp, films).write();
}

}  // namespace tubemesh::io
