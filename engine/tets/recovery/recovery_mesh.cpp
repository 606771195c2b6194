#include "engine/tets/recovery/recovery_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "engine/mesh/topology.hpp"

namespace tubemesh::tets {

using delaunay::kFreeSlot;
using delaunay::kNoAdjacent;

namespace {

int local_of(const index_t* v, index_t x) {
    for (int i = 0; i < 4; ++i)
        if (v[i] == x) return i;
    return -1;
}

// +1 when (v[i0], v[i1], v[i2], v[i3]) is an even permutation of the tet's row (so positively
// oriented, as every tet is), -1 when odd.
int permutation_sign(int i0, int i1, int i2, int i3) {
    const int p[4] = {i0, i1, i2, i3};
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
    return inversions % 2 == 0 ? 1 : -1;
}

}  // namespace

RecoveryMesh::RecoveryMesh(std::vector<double> xyz, delaunay::TetStore&& tets)
    : xyz_(std::move(xyz)), tets_(std::move(tets)) {
    incident_.assign(point_count(), kNoIndex);
    for (index_t t = 0; t < tets_.size(); ++t)
        for (int i = 0; i < 4; ++i) incident_[tets_.vertex(t)[i]] = t;
}

index_t RecoveryMesh::append_slot() {
    const index_t t = tets_.size();
    if (std::size_t{t} + 1 > tets_.capacity()) tets_.reserve(std::size_t{t} + t / 2 + 64);
    tets_.set_size(t + 1);
    return t;
}

index_t RecoveryMesh::add_point(const double* p) {
    xyz_.insert(xyz_.end(), p, p + 3);
    incident_.push_back(kNoIndex);
    return point_count() - 1;
}

std::uint32_t SlotMarks::next(index_t slots) {
    if (mark_.size() < slots) mark_.resize(slots, 0);
    if (++epoch_ == 0) {
        std::fill(mark_.begin(), mark_.end(), 0u);
        epoch_ = 1;
    }
    return epoch_;
}

void RecoveryMesh::ball(index_t v, std::vector<index_t>& out, SlotMarks& marks) const {
    out.clear();
    const index_t t0 = incident_[v];
    if (t0 == kNoIndex) return;
    const std::uint32_t e = marks.next(slot_count());
    out.push_back(t0);
    marks.set(t0, e);
    for (std::size_t k = 0; k < out.size(); ++k) {
        const index_t t = out[k];
        const int iv = local_of(vertex(t), v);
        for (int f = 0; f < 4; ++f) {
            if (f == iv) continue;
            const index_t n = tets_.neighbour(4 * t + static_cast<index_t>(f));
            if (n == kNoAdjacent || marks.marked(n >> 2, e)) continue;
            marks.set(n >> 2, e);
            out.push_back(n >> 2);
        }
    }
}

index_t RecoveryMesh::find_edge(index_t a, index_t b, std::vector<index_t>& around, SlotMarks& marks) const {
    ball(a, around, marks);
    return edge_in(around, b);
}

index_t RecoveryMesh::edge_in(std::span<const index_t> ball_of_a, index_t b) const {
    for (index_t t : ball_of_a)
        if (local_of(vertex(t), b) >= 0) return t;
    return kNoIndex;
}

bool RecoveryMesh::edge_ring(index_t a, index_t b, std::vector<index_t>& tets, std::vector<index_t>& ring) {
    tets.clear();
    ring.clear();
    const index_t t0 = find_edge(a, b);
    if (t0 == kNoIndex) return false;
    const index_t* v = vertex(t0);
    const int ia = local_of(v, a), ib = local_of(v, b);
    int k = 0;
    while (k == ia || k == ib) ++k;
    const int l = 6 - ia - ib - k;
    index_t from = v[k], to = v[l];
    if (permutation_sign(ia, ib, k, l) < 0) std::swap(from, to);
    index_t cur = t0;
    for (int guard = 0; guard < 4096; ++guard) {
        ring.push_back(from);
        tets.push_back(cur);
        const index_t n = tets_.neighbour(4 * cur + static_cast<index_t>(local_of(vertex(cur), from)));
        if (n == kNoAdjacent) return false;
        if ((n >> 2) == t0) return true;
        cur = n >> 2;
        from = to;
        to = vertex(cur)[n & 3];
    }
    throw Error("boundary recovery: internal error, the tets around an edge do not close up");
}

std::array<index_t, 3> RecoveryMesh::face(index_t t, int f) const {
    const auto& node = kTetTopology.face[f].node;
    const index_t* v = vertex(t);
    return {v[node[0]], v[node[1]], v[node[2]]};
}

// The first tet found on each side: a face of a valid mesh has at most one there, and ball()
// lists a vertex's tets in one fixed order, so the answer is the same however it is reached.
RecoveryMesh::FaceSides RecoveryMesh::face_in(std::span<const index_t> ball_of_a, index_t a, index_t b,
                                              index_t c) const {
    FaceSides sides;
    for (index_t t : ball_of_a) {
        const index_t* v = vertex(t);
        const int ib = local_of(v, b), ic = local_of(v, c);
        if (ib < 0 || ic < 0) continue;
        const int ia = local_of(v, a);
        const int id = 6 - ia - ib - ic;
        const int side = permutation_sign(ia, ib, ic, id) > 0 ? 1 : 0;
        if (sides.tet[side] != kNoIndex) continue;
        sides.tet[side] = t;
        sides.local[side] = id;
        if (sides.tet[1 - side] != kNoIndex) break;
    }
    return sides;
}

bool RecoveryMesh::replace(std::span<const index_t> old_tets, std::span<const Tet> new_tets,
                           std::vector<index_t>* added) {
    const std::uint32_t e = next_epoch();
    for (index_t t : old_tets) set_mark(t, e);
    boundary_.clear();
    for (index_t t : old_tets) {
        for (int f = 0; f < 4; ++f) {
            const index_t n = tets_.neighbour(4 * t + static_cast<index_t>(f));
            if (n != kNoAdjacent && marked(n >> 2, e)) continue;
            const auto fv = face(t, f);
            boundary_.push_back({sorted3(fv[0], fv[1], fv[2]), n, false});
        }
    }
    // Match faces before touching the mesh: to another new tet, else to the old set's outside.
    // partner[i] = other new face (< 4k) or 4k + boundary entry.
    const std::size_t nf = 4 * new_tets.size();
    std::vector<std::array<index_t, 3>> keys(nf);
    for (std::size_t i = 0; i < new_tets.size(); ++i)
        for (int f = 0; f < 4; ++f) {
            const auto& node = kTetTopology.face[f].node;
            keys[4 * i + f] = sorted3(new_tets[i][node[0]], new_tets[i][node[1]], new_tets[i][node[2]]);
        }
    std::vector<std::size_t> partner(nf, SIZE_MAX);
    for (std::size_t i = 0; i < nf; ++i) {
        if (partner[i] != SIZE_MAX) continue;
        for (std::size_t j = i + 1; j < nf && partner[i] == SIZE_MAX; ++j)
            if (partner[j] == SIZE_MAX && keys[j] == keys[i]) {
                partner[i] = j;
                partner[j] = i;
            }
        for (std::size_t j = 0; j < boundary_.size() && partner[i] == SIZE_MAX; ++j)
            if (!boundary_[j].used && boundary_[j].key == keys[i]) {
                boundary_[j].used = true;
                partner[i] = nf + j;
            }
        if (partner[i] == SIZE_MAX) return false;
    }
    for (const BoundaryFace& b : boundary_)
        if (!b.used) return false;

    // Slots: the old ones first, then free ones, then new rows.
    std::vector<index_t> slots;
    slots.reserve(new_tets.size());
    for (index_t t : old_tets) {
        for (int i = 0; i < 4; ++i)
            if (incident_[tets_.vertex(t)[i]] == t) incident_[tets_.vertex(t)[i]] = kNoIndex;
        tets_.vertex(t)[0] = kFreeSlot;
    }
    std::size_t reused = 0;
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        if (reused < old_tets.size()) {
            slots.push_back(old_tets[reused++]);
        } else if (!free_.empty()) {
            slots.push_back(free_.back());
            free_.pop_back();
        } else {
            slots.push_back(append_slot());
        }
    }
    for (; reused < old_tets.size(); ++reused) free_.push_back(old_tets[reused]);
    for (std::size_t i = 0; i < new_tets.size(); ++i)
        for (int k = 0; k < 4; ++k) {
            tets_.vertex(slots[i])[k] = new_tets[i][k];
            incident_[new_tets[i][k]] = slots[i];
        }
    for (std::size_t i = 0; i < nf; ++i) {
        const index_t code = 4 * slots[i / 4] + static_cast<index_t>(i % 4);
        if (partner[i] < nf) {
            tets_.neighbour(code) = 4 * slots[partner[i] / 4] + static_cast<index_t>(partner[i] % 4);
        } else {
            const index_t out = boundary_[partner[i] - nf].outside;
            tets_.neighbour(code) = out;
            if (out != kNoAdjacent) tets_.neighbour(out) = code;
        }
    }
    if (added) *added = std::move(slots);
    return true;
}

delaunay::TetStore RecoveryMesh::release(std::span<const std::uint8_t> keep) {
    std::vector<index_t> new_id(slot_count(), kNoIndex);
    index_t n = 0;
    for (index_t t = 0; t < slot_count(); ++t)
        if (alive(t) && keep[t]) new_id[t] = n++;
    // new_id[t] <= t: row new_id[t] is t's own or one already moved down.
    for (index_t t = 0; t < slot_count(); ++t) {
        const index_t to = new_id[t];
        if (to == kNoIndex) continue;
        for (int i = 0; i < 4; ++i) {
            tets_.vertex(to)[i] = tets_.vertex(t)[i];
            const index_t nb = tets_.neighbour(4 * t + static_cast<index_t>(i));
            tets_.neighbour(4 * to + static_cast<index_t>(i)) =
                (nb == kNoAdjacent || new_id[nb >> 2] == kNoIndex) ? kNoAdjacent : 4 * new_id[nb >> 2] + (nb & 3);
        }
    }
    tets_.set_size(n);
    tets_.shrink_to_fit();
    incident_.clear();
    free_.clear();
    return std::move(tets_);
}

}  // namespace tubemesh::tets
