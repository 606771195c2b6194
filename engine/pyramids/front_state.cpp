#include "engine/pyramids/front_state.hpp"

#include <algorithm>
#include <string>

namespace tubemesh::pyramids {

namespace {

// Rows of `count` keys: item i (of `size`) goes into row key(i), rows keep the items ascending.
template <class KeyOf>
Adjacency rows_of(std::size_t count, std::size_t size, KeyOf key) {
    Adjacency rows;
    rows.offset.assign(count + 1, 0);
    for (std::size_t i = 0; i < size; ++i) ++rows.offset[key(i) + 1];
    for (std::size_t r = 0; r < count; ++r) rows.offset[r + 1] += rows.offset[r];
    rows.items.resize(size);
    std::vector<std::size_t> next(rows.offset.begin(), rows.offset.end() - 1);
    for (std::size_t i = 0; i < size; ++i) rows.items[next[key(i)]++] = static_cast<index_t>(i);
    return rows;
}

}  // namespace

FrontState::FrontState(const HybridMesh& mesh, std::span<const Front> fronts,
                       std::span<const index_t> boundary_triangles)
    : mesh_(mesh),
      fronts_(fronts),
      mesh_points_(mesh.point_count()),
      live_(mesh.point_count(), 0),
      apex_(fronts.size(), kNoIndex),
      how_(fronts.size(), kHowNone),
      partner_(fronts.size(), {kNoIndex, kNoIndex, kNoIndex, kNoIndex}) {
    const std::size_t nb = boundary_triangles.size() / 3;
    boundary_.resize(nb);
    boundary_partner_.assign(nb, kNoIndex);
    for (std::size_t b = 0; b < nb; ++b) {
        const index_t* t = boundary_triangles.data() + 3 * b;
        boundary_[b] = {t[0], t[2], t[1]};  // reversed: the front looks into the tet region
        count(boundary_[b], +1);
    }
    boundary_at_ = rows_of(mesh_points_, nb, [&](std::size_t b) { return key(boundary_[b]).a; });
    for (std::size_t b = 0; b < nb; ++b) {
        const Key k = key(boundary_[b]);
        for (index_t other : boundary_at_.row(k.a)) {
            if (other >= b) break;
            if (key(boundary_[other]) == k)
                throw Error("pyramids: boundary triangles " + std::to_string(other) + " and " + std::to_string(b) +
                            " have the same three nodes; the surface mesh must not repeat a triangle");
        }
    }
    corner_of_ = rows_of(mesh_points_, 4 * fronts.size(), [&](std::size_t c) { return fronts[c / 4].node[c % 4]; });
    for (index_t& c : corner_of_.items) c /= 4;
    for (const Front& f : fronts)
        for (index_t n : f.node) ++live_[n];
}

FrontState::Key FrontState::key(const Triangle& t) {
    Key k{t[0], t[1], t[2]};
    if (k.a > k.b) std::swap(k.a, k.b);
    if (k.b > k.c) std::swap(k.b, k.c);
    if (k.a > k.b) std::swap(k.a, k.b);
    return k;
}

void FrontState::count(const Triangle& t, int delta) {
    for (index_t n : t) live_[n] = static_cast<index_t>(static_cast<int>(live_[n]) + delta);
}

Triangle FrontState::lateral(index_t front, int f) const {
    const auto& q = fronts_[front].node;
    return {q[static_cast<std::size_t>(f)], q[static_cast<std::size_t>((f + 1) % 4)], apex_[front]};
}

index_t FrontState::find(const Key& k, index_t skip) const {
    if (k.c < mesh_points_)
        for (index_t b : boundary_at_.row(k.a))
            if (boundary_partner_[b] == kNoIndex && key(boundary_[b]) == k) return kBoundaryOwner | b;
    // One of the two smallest nodes is a corner of the front owning a lateral face: only one
    // of its three nodes is not.
    for (const index_t n : {k.a, k.b}) {
        if (n >= mesh_points_) break;
        for (index_t j : corner_of_.row(n)) {
            if (j == skip || apex_[j] == kNoIndex) continue;
            for (int f = 0; f < 4; ++f)
                if (partner_[j][f] == kNoIndex && key(lateral(j, f)) == k) return 4 * j + static_cast<index_t>(f);
        }
    }
    return kNoIndex;
}

index_t FrontState::find(const Triangle& t) const { return find(key(t), kNoIndex); }

Triangle FrontState::triangle(index_t owner) const {
    if (owner & kBoundaryOwner) return boundary_[owner & ~kBoundaryOwner];
    return lateral(owner / 4, static_cast<int>(owner % 4));
}

void FrontState::set_partner(index_t owner, index_t partner) {
    if (owner & kBoundaryOwner)
        boundary_partner_[owner & ~kBoundaryOwner] = partner;
    else
        partner_[owner / 4][owner % 4] = partner;
}

void FrontState::add_pyramid(index_t front, const Choice& choice) {
    index_t apex = choice.node;
    const bool fresh = apex == kNoIndex;  // a new node: no triangle holds it yet
    if (fresh) {
        apex = mesh_points_ + static_cast<index_t>(apexes_.size());
        apexes_.push_back(choice.position);
        apex_uses_.push_back(0);
        live_.push_back(0);
    }
    if (apex >= mesh_points_) ++apex_uses_[apex - mesh_points_];
    apex_[front] = apex;
    how_[front] = choice.how;
    for (index_t n : fronts_[front].node) --live_[n];  // the base quad leaves the front
    for (int f = 0; f < 4; ++f) {
        const Triangle t = lateral(front, f);
        const index_t self = 4 * front + static_cast<index_t>(f);
        const index_t other = fresh ? kNoIndex : find(key(t), front);
        if (other == kNoIndex) {
            count(t, +1);
            continue;
        }
        // The criteria refused same-orientation repeats, and fronts of one batch never touch
        // each other's faces: a match here is the opposite face of a neighbour, which now
        // lies between two elements and leaves the front.
        if (same_orientation(triangle(other), t))
            throw Error("pyramids: internal error: pyramid face repeats a front face with the same orientation");
        partner_[front][f] = other;
        set_partner(other, self);
        count(t, -1);
    }
}

void FrontState::remove_pyramid(index_t front) {
    for (int f = 0; f < 4; ++f) {
        const Triangle t = lateral(front, f);
        const index_t other = partner_[front][f];
        if (other == kNoIndex) {
            count(t, -1);
        } else {
            // The face it covered is back on the front.
            set_partner(other, kNoIndex);
            count(t, +1);
            partner_[front][f] = kNoIndex;
        }
    }
    for (index_t n : fronts_[front].node) ++live_[n];
    const index_t apex = apex_[front];
    if (apex >= mesh_points_) --apex_uses_[apex - mesh_points_];
    apex_[front] = kNoIndex;
    how_[front] = kHowNone;
}

}  // namespace tubemesh::pyramids
