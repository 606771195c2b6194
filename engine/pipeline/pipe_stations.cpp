#include "engine/pipeline/pipe_stations.hpp"

#include <algorithm>
#include <string>

namespace tubemesh {

namespace {

// The join at tube t's end e, if any: the other tube and its end.
struct Neighbour {
    index_t tube = kNoIndex;
    int end = 0;
};

Neighbour joined_at(const std::vector<RingJoin>& joins, index_t t, int e) {
    for (const RingJoin& j : joins) {
        if (j.tube_a == t && j.end_a == e) return {j.tube_b, j.end_b};
        if (j.tube_b == t && j.end_b == e) return {j.tube_a, j.end_a};
    }
    return {};
}

// Station i of `ring` walked from end `from`: i itself from end 0, counted back from end 1.
index_t walked(const TubeRing& ring, int from, index_t i) { return from == 0 ? i : ring.stations - 1 - i; }

void add_station(const TubeRing& ring, index_t station, PipeStations& pipe) {
    pipe.centres.push_back(ring.centres[station]);
    for (index_t k = 0; k < ring.circumferential; ++k) pipe.wall_nodes.push_back(ring.node(station, 0, k));
}

// The chain of rings from tube `first`'s free end `from`: the first ring whole, each joined
// one without its first station (its nodes there became the previous ring's).
PipeStations chain(const SweepResult& sweep, const std::vector<RingJoin>& joins, index_t first, int from,
                   const std::string& name) {
    PipeStations pipe;
    pipe.name = name;
    pipe.circumferential = sweep.rings[first].circumferential;
    index_t t = first;
    int e = from;
    for (std::size_t visited = 0;; ++visited) {
        if (visited == sweep.rings.size())
            throw Error(name + " is a closed loop of joined tubes: a water network needs an inlet and an outlet");
        const TubeRing& ring = sweep.rings[t];
        for (index_t i = t == first ? 0 : 1; i < ring.stations; ++i) add_station(ring, walked(ring, e, i), pipe);
        const Neighbour next = joined_at(joins, t, 1 - e);
        if (next.tube == kNoIndex) break;
        t = next.tube;
        e = next.end;
    }
    return pipe;
}

bool same_nodes(std::vector<index_t> a, const std::vector<index_t>& sorted) {
    std::sort(a.begin(), a.end());
    return a == sorted;
}

}  // namespace

void add_pipe_stations(const SweepResult& sweep, const std::vector<RingJoin>& joins, const HybridMesh& mesh,
                       MeshDescription& description) {
    const std::vector<index_t> pipe_of = pipe_of_tubes(sweep.rings.size(), joins);
    std::vector<bool> done;
    for (const TubeRing& ring : sweep.rings) {
        const index_t p = pipe_of[ring.tube];
        if (p < done.size() && done[p]) continue;
        done.resize(std::max<std::size_t>(done.size(), p + 1), false);
        done[p] = true;
        // A free end of this pipe: walk the chain from it (this tube's, or found along the chain).
        index_t first = kNoIndex;
        int from = 0;
        for (const TubeRing& r : sweep.rings)
            for (int e = 0; e < 2 && first == kNoIndex; ++e)
                if (pipe_of[r.tube] == p && joined_at(joins, r.tube, e).tube == kNoIndex) {
                    first = r.tube;
                    from = e;
                }
        const std::string& name = mesh.surface_group_names[ring.wall_group];
        if (first == kNoIndex)
            throw Error(name + " is a closed loop of joined tubes: a water network needs an inlet and an outlet");
        PipeStations pipe = chain(sweep, joins, first, from, name);
        // From the rim named "_inlet" (add_rims), so the network's inlet is that end.
        const auto inlet = std::find_if(description.node_sets.begin(), description.node_sets.end(),
                                        [&](const NamedNodeSet& s) { return s.name == name + "_inlet"; });
        const std::size_t n = pipe.circumferential;
        const std::vector<index_t> last(pipe.wall_nodes.end() - static_cast<std::ptrdiff_t>(n), pipe.wall_nodes.end());
        if (inlet != description.node_sets.end() && same_nodes(last, inlet->nodes)) {
            std::reverse(pipe.centres.begin(), pipe.centres.end());
            std::vector<index_t> reversed;
            for (std::size_t s = pipe.centres.size(); s-- > 0;)
                reversed.insert(reversed.end(), pipe.wall_nodes.begin() + static_cast<std::ptrdiff_t>(s * n),
                                pipe.wall_nodes.begin() + static_cast<std::ptrdiff_t>((s + 1) * n));
            pipe.wall_nodes = std::move(reversed);
        }
        description.pipes.push_back(std::move(pipe));
    }
}

}  // namespace tubemesh
