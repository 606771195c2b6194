#include "engine/pyramids/criteria.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

#include "engine/mesh/edge_key.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/pyramids/contacts.hpp"
#include "engine/pyramids/front_link.hpp"
#include "engine/pyramids/new_pyramid.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh::pyramids {

namespace {

using predicates::orient3d;

double face_distance2(const VisibleFace& face, const Vec3& p) {
    double d2 = point_triangle_distance2(p, face.p[0], face.p[1], face.p[2]);
    if (face.size == 4) d2 = std::min(d2, point_triangle_distance2(p, face.p[0], face.p[2], face.p[3]));
    return d2;
}

// x strictly inside the pyramid: strictly inside its four lateral faces (each oriented out of
// the pyramid, so the inside is where orient3d is negative) and strictly above its base. Not
// "inside one of its sub-tets": a point on the plane of a base diagonal, the pyramid's axis
// for one, is inside no sub-tet strictly. A non-planar base is taken at its highest: above
// any of the four triangles its two diagonals make, which can only refuse more.
bool inside_pyramid(const NewPyramid& y, const Vec3& x) {
    const auto& p = y.p;
    for (int f = 0; f < 4; ++f)
        if (orient3d(p[f], p[(f + 1) % 4], p[4], x) >= 0) return false;
    return orient3d(p[0], p[1], p[2], x) > 0 || orient3d(p[0], p[2], p[3], x) > 0 || orient3d(p[0], p[1], p[3], x) > 0 ||
           orient3d(p[1], p[2], p[3], x) > 0;
}

// Existing faces and edges the candidate would reuse (only an existing node can). A repeated
// face must be the opposite face of a neighbour; then the two pyramids share it.
bool match_existing(NewPyramid& y, const Visible& vis, const FrontState& state) {
    const index_t apex = y.node[4];
    if (apex == kNoIndex) return true;
    for (int f = 0; f < 4; ++f) {
        const Triangle t{y.node[f], y.node[(f + 1) % 4], apex};
        const index_t owner = state.find(t);
        if (owner == kNoIndex) continue;
        if (same_orientation(state.triangle(owner), t)) return false;
        y.face_new[f] = false;
    }
    for (int k = 0; k < 4; ++k) y.edge_new[k] = !vis.has_edge(y.node[k], apex);
    return true;
}

bool too_close_to_face(const NewPyramid& y, const Visible& vis, double d2min) {
    const Vec3& apex = y.p[4];
    for (const VisibleFace& face : vis.faces) {
        if (y.node[4] != kNoIndex && face.has(y.node[4])) continue;
        if (box_distance2(face.box, apex) >= d2min) continue;
        if (face_distance2(face, apex) < d2min) return true;
    }
    return false;
}

// The visible face nearest to p among those nearer than sqrt(d2min) (a new node contains no
// face's node, so none is skipped): the point of it nearest to p and, but for an obstacle
// (which has no orientation), the normal of the triangle holding that point, pointing into
// the unmeshed region. False when no face is that near.
struct NearFace {
    Vec3 point;
    Vec3 normal;  // zero for an obstacle
};

bool nearest_close_face(const Vec3& p, const Visible& vis, double d2min, NearFace& out) {
    double best = d2min;
    bool found = false;
    auto consider = [&](const VisibleFace& face, const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 q = closest_point_on_triangle(p, a, b, c);
        const double d2 = distance2(p, q);
        if (!(d2 < best)) return;
        best = d2;
        found = true;
        out.point = q;
        out.normal = face.role == FaceRole::Obstacle ? Vec3{0, 0, 0} : cross(b - a, c - a);
    };
    for (const VisibleFace& face : vis.faces) {
        if (box_distance2(face.box, p) >= best) continue;
        consider(face, face.p[0], face.p[1], face.p[2]);
        if (face.size == 4) consider(face, face.p[0], face.p[2], face.p[3]);
    }
    return found;
}

bool contains_node(const NewPyramid& y, const Visible& vis) {
    for (const NearNode& n : vis.nodes) {
        if (y.has(n.id) || box_distance2(y.box, n.p) > 0) continue;
        if (inside_pyramid(y, n.p)) return true;
    }
    return false;
}

// Edges of the front faces around an existing candidate node P (its fan), as pair keys.
// At most kFanEdges: the rest of a larger fan is not skipped, which only makes the check
// stricter.
constexpr int kFanEdges = 96;
struct ApexFan {
    int count = 0;
    std::array<std::uint64_t, kFanEdges> key;
    bool has(index_t a, index_t b) const {
        const std::uint64_t k = edge_key(a, b);
        for (int i = 0; i < count; ++i)
            if (key[i] == k) return true;
        return false;
    }
};

void collect_fan(index_t apex, const Visible& vis, ApexFan& fan) {
    if (apex == kNoIndex) return;
    vis.for_each_face_of(apex, [&](const VisibleFace& face) {
        for (int k = 0; k < face.size && fan.count < kFanEdges; ++k)
            fan.key[fan.count++] = edge_key(face.node[k], face.node[(k + 1) % face.size]);
    });
}

// The boxes of the lateral edges (corner k to the apex), each inside the pyramid's box.
std::array<Box, 4> lateral_edge_boxes(const NewPyramid& y) {
    std::array<Box, 4> box;
    for (int k = 0; k < 4; ++k) {
        box[k] = Box::of(y.p[k]);
        box[k].add(y.p[4]);
    }
    return box;
}

// "The distance between the new edges and visible edges": a new edge X-P fails where it
// comes nearer to a front edge than the threshold and than its base corner X already is.
// Not measured: edges that touch the base's immediate neighbourhood (an end is a node of a
// front face at a base corner) or the fan of an existing apex. A new edge leaves the base
// corner X across those faces, so its nearness to such edges is the angle it makes with
// them — which the apex-to-face distance already bounds — times the size of the input's
// triangles there; no apex position can change the latter. A host face, for one, lies a
// fixed half axial step below the end pyramids of a ring whatever their apex, and its
// triangles next to the ring run under their lateral faces.
bool too_close_to_edge(const NewPyramid& y, const Visible& vis, double d2min) {
    const index_t apex = y.node[4];
    ApexFan fan;
    collect_fan(apex, vis, fan);
    const std::array<Box, 4> ebox = lateral_edge_boxes(y);
    // Any pair fails the candidate, so the front's edges come first: one that is the threshold
    // away from the pyramid's box is as far from every new edge, whose boxes lie inside it.
    for (const VisibleEdge& e : vis.edges) {
        if (e.near_base) continue;
        if (apex != kNoIndex && (e.a == apex || e.b == apex)) continue;
        if (box_distance2(y.box, e.box) >= d2min) continue;
        for (int k = 0; k < 4; ++k) {
            if (!y.edge_new[k]) continue;
            if (box_distance2(ebox[k], e.box) >= d2min) continue;
            const Vec3& x = y.p[k];
            const double d2 = segment_segment_distance2(x, y.p[4], e.pa, e.pb);
            if (d2 >= d2min) continue;
            // Relative slack: when the nearest point is X itself the two computations agree
            // up to rounding.
            if (!(d2 < segment_segment_distance2(x, x, e.pa, e.pb) * (1.0 - 1e-9))) continue;
            if (fan.count > 0 && fan.has(e.a, e.b)) continue;
            return true;
        }
    }
    return false;
}

// As above, faces first: one whose box misses the pyramid's misses every new edge's. A new
// apex shares no node with a face, so a new edge shares at most its base corner with one of
// the face's triangles; leaving that corner off the triangle's plane, it meets it there only.
bool edge_crosses_face(const NewPyramid& y, const Visible& vis) {
    const std::array<Box, 4> ebox = lateral_edge_boxes(y);
    const index_t b = y.node[4];
    for (const VisibleFace& face : vis.faces) {
        if (face.role == FaceRole::Own || !face.box.overlaps(y.box)) continue;
        // Per triangle of the face: 1 the apex is surely off its plane, 0 not known, -1 not asked.
        std::array<int, 2> apex_off{-1, -1};
        for (int k = 0; k < 4; ++k) {
            if (!y.edge_new[k] || !face.box.overlaps(ebox[k])) continue;
            const index_t a = y.node[k];
            // Both ends on a quad that has no such edge: the new edge is its diagonal.
            if (face.size == 4 && face.has(a) && b != kNoIndex && face.has(b)) return true;
            for (int tri = 0; tri < face.size - 2; ++tri) {
                const int c1 = tri + 1, c2 = tri + 2;  // triangles (0, 1, 2) and (0, 2, 3)
                const std::array<index_t, 3> it{face.node[0], face.node[c1], face.node[c2]};
                const std::array<const Vec3*, 3> t{&face.p[0], &face.p[c1], &face.p[c2]};
                if (b == kNoIndex && (a == it[0] || a == it[1] || a == it[2])) {
                    if (apex_off[tri] < 0) apex_off[tri] = PlaneFilter(*t[0], *t[1], *t[2]).surely_off(*t[0], y.p[4]);
                    if (apex_off[tri] == 1) continue;
                }
                if (improper_contact(a, y.p[k], b, y.p[4], it, t, y)) return true;
            }
        }
    }
    return false;
}

// A side of the base quad. It meets the pyramid's lateral faces at their shared nodes only,
// once its four sub-tets are positive (judge checks that first): each lateral face's plane has
// the two other corners strictly on one side, those sub-tets' orientations.
bool base_side(const NewPyramid& y, const VisibleEdge& e) {
    for (int k = 0; k < 4; ++k) {
        const index_t u = y.node[k], v = y.node[(k + 1) % 4];
        if ((e.a == u && e.b == v) || (e.a == v && e.b == u)) return true;
    }
    return false;
}

// Edges first, as above: one whose box misses the pyramid's misses every lateral face's. A
// front edge with one end at a base corner of a lateral face (a new apex is no edge's end)
// meets the face only there when its other end is off the face's plane.
bool face_crosses_edge(const NewPyramid& y, const Visible& vis) {
    std::array<Box, 4> tbox;
    const std::array<PlaneFilter, 4> plane{PlaneFilter(y.p[0], y.p[1], y.p[4]), PlaneFilter(y.p[1], y.p[2], y.p[4]),
                                           PlaneFilter(y.p[2], y.p[3], y.p[4]), PlaneFilter(y.p[3], y.p[0], y.p[4])};
    for (int f = 0; f < 4; ++f) {
        tbox[f] = Box::of(y.p[f]);
        tbox[f].add(y.p[(f + 1) % 4]);
        tbox[f].add(y.p[4]);
    }
    const bool new_apex = y.node[4] == kNoIndex;
    for (const VisibleEdge& e : vis.edges) {
        if (!e.box.overlaps(y.box) || base_side(y, e)) continue;
        for (int f = 0; f < 4; ++f) {
            if (!y.face_new[f] || !e.box.overlaps(tbox[f])) continue;
            const int g = (f + 1) % 4;
            if (new_apex) {
                // Not both ends at f and g: that is a base side, skipped above.
                const int at = e.a == y.node[f] || e.b == y.node[f] ? f : e.a == y.node[g] || e.b == y.node[g] ? g : -1;
                if (at >= 0 && plane[f].surely_off(y.p[at], e.a == y.node[at] ? e.pb : e.pa)) continue;
            }
            const std::array<index_t, 3> it{y.node[f], y.node[g], y.node[4]};
            const std::array<const Vec3*, 3> t{&y.p[f], &y.p[g], &y.p[4]};
            if (improper_contact(e.a, e.pa, e.b, e.pb, it, t, y)) return true;
        }
    }
    return false;
}

}  // namespace

Thresholds Thresholds::at(const Front& f, const PyramidOptions& opt, double rate) {
    Thresholds t;
    const double degrees = opt.max_angle_degrees / rate;
    t.cos_max_angle = degrees >= 90.0 ? 0.0 : std::cos(degrees * std::numbers::pi / 180.0);
    const double d = opt.distance_factor * f.spacing * rate;
    t.min_distance2 = d * d;
    return t;
}

bool move_off_faces(const Front& f, const Thresholds& t, const Visible& vis, Vec3& p) {
    const double target = std::sqrt(t.min_distance2) * (1.0 + 1e-6);
    const double reach2 = f.reach * f.reach;
    bool moved = false;
    for (int step = 0;; ++step) {
        NearFace near;
        if (!nearest_close_face(p, vis, t.min_distance2, near)) return moved;
        // Still near some face after the last move: the faces around p leave no room.
        if (step == kMoveSteps) return false;
        const double area = norm(near.normal);
        if (area > 0) {
            // An oriented face: to the target distance in front of its plane, whichever side p
            // is on (a try node can lie behind a face that leans over the quad). The distance
            // to the triangle is at least that to its plane, and the move is at most twice the
            // threshold, since p was within it.
            const Vec3 n = (1.0 / area) * near.normal;
            p = p + (target - dot(p - near.point, n)) * n;
        } else {
            const Vec3 away = p - near.point;
            const double d = norm(away);
            if (!(d > 0)) return false;  // on an obstacle: no side to leave it by
            p = p + ((target - d) / d) * away;
        }
        moved = true;
        if (distance2(p, f.ideal) >= reach2) return false;
    }
}

Verdict judge(const Front& f, const Candidate& c, const Thresholds& t, const Visible& vis, const FrontState& state) {
    const Vec3 mp = c.p - f.centroid;
    const double length = norm(mp);
    if (!(length > 0) || !(dot(mp, f.normal) > t.cos_max_angle * length)) return Verdict::AngleTooLarge;

    NewPyramid y;
    for (int k = 0; k < 4; ++k) {
        y.node[k] = f.node[k];
        y.p[k] = f.corner[k];
    }
    y.node[4] = c.id;
    y.p[4] = c.p;
    const auto& p = y.p;
    if (orient3d(p[0], p[1], p[2], p[4]) <= 0 || orient3d(p[0], p[2], p[3], p[4]) <= 0 ||
        orient3d(p[0], p[1], p[3], p[4]) <= 0 || orient3d(p[1], p[2], p[3], p[4]) <= 0)
        return Verdict::NotPositive;
    if (f.quality_floor > 0) {
        const bool ideal = c.id == kNoIndex && std::memcmp(&c.p, &f.ideal, sizeof(Vec3)) == 0;
        const double quality = ideal ? f.ideal_quality : pyramid_scaled_jacobian({p[0], p[1], p[2], p[3], p[4]});
        if (quality < f.quality_floor) return Verdict::LowQuality;
    }
    if (!match_existing(y, vis, state)) return Verdict::FaceMismatch;
    if (!keeps_front_manifold(y, vis)) return Verdict::PinchesFront;

    y.box = Box::of(p[0]);
    for (int k = 1; k < 5; ++k) y.box.add(p[k]);
    if (too_close_to_face(y, vis, t.min_distance2)) return Verdict::TooCloseToFace;
    if (contains_node(y, vis)) return Verdict::ContainsNode;
    if (too_close_to_edge(y, vis, t.min_distance2)) return Verdict::TooCloseToEdge;
    if (edge_crosses_face(y, vis)) return Verdict::EdgeCrossesFace;
    if (face_crosses_edge(y, vis)) return Verdict::FaceCrossesEdge;
    return Verdict::Accepted;
}

}  // namespace tubemesh::pyramids
