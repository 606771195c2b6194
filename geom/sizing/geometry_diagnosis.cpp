#include "geom/sizing/geometry_diagnosis.hpp"

#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {

namespace {

std::string face_list(const std::vector<int>& faces, const char* comma = ", ") {
    std::string s;
    for (int f : faces) s += (s.empty() ? "" : comma) + std::to_string(f);
    return s;
}

// A distance as a message gives it: walls that touch measure a few 1e-13 either side of zero,
// and within 1e-6 of the radius the message says they touch, at 0.
double shown(double distance, double radius) { return distance <= 1e-6 * radius ? 0.0 : distance; }

std::string pipe(const TubeInfo& t) {
    return fmt::format("the pipe of wall face{} {}", t.faces.size() == 1 ? "" : "s", face_list(t.faces));
}

RingDrop drop_of(const TubeInfo& t, std::string reason, std::string warning) {
    return {t.faces, t.radius_min, t.length, std::move(reason), std::move(warning)};
}

}  // namespace

void refuse_self_contact(const Model& model) {
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(solid_of(model), TopAbs_EDGE, TopAbs_FACE, edge_faces);
    for (int e = 1; e <= edge_faces.Extent(); ++e) {
        std::set<int> faces;  // a seam lists its face twice
        for (const TopoDS_Shape& f : edge_faces(e)) faces.insert(model.impl().faces.FindIndex(f));
        if (faces.size() <= 2) continue;
        throw Error(fmt::format(
            "the solid's boundary touches itself along {} (faces {} meet there): a pipe wall tangent to a face or to "
            "another pipe along a line leaves no room for any element there, and no conforming mesh exists; move the "
            "pipe off the face or the other pipe (at least a tenth of its diameter) or join them in the CAD model",
            Model::edge_name(model.impl().edges.FindIndex(edge_faces.FindKey(e))),
            face_list(std::vector<int>(faces.begin(), faces.end()))));
    }
}

std::vector<RingDrop> walls_without_ring(const TubeSearch& tubes, int face_count) {
    std::vector<RingDrop> out;
    for (const TubeRejection& r : tubes.rejected) {
        if (r.faces.empty()) continue;
        if (r.crease) {
            out.push_back({r.faces, 0, 0, "pipe walls overlap",
                           fmt::format("faces {} form one hole whose curved walls meet along the axis at an angle "
                                       "({}), as pipes that overlap do: no hex ring fits it, so it is meshed with "
                                       "tetrahedra; for hex rings, keep the pipes at least a tenth of a diameter "
                                       "apart or make them one pipe in the CAD model",
                                       face_list(r.faces, ","), r.reason)});
            continue;
        }
        if (r.loops > 2) {
            out.push_back({r.faces, 0, 0, "pipe walls meet",
                           fmt::format("faces {} are pipe walls that meet each other ({} open ends where a pipe has "
                                       "2: pipes that cross or touch, or a T-junction): no hex ring, meshed with "
                                       "tetrahedra; for hex rings, move the pipes apart (at least a tenth of a "
                                       "diameter between the walls) or join them into one pipe in the CAD model",
                                       face_list(r.faces), r.loops)});
            continue;
        }
        // No open end, or one (another pipe's hole) in a group holding most of the solid: the
        // smooth flood from a hole ran along a wall into the host's faces, so a wall is tangent
        // to one of them. A blind hole's group is its wall and bottom only.
        const bool most_faces = r.faces.size() >= 3 && 2 * r.faces.size() > static_cast<std::size_t>(face_count);
        if (r.loops == 0 || (r.loops == 1 && most_faces))
            out.push_back({r.faces, 0, 0, "pipe wall tangent to a face",
                           fmt::format("faces {} join smoothly into one group that runs from a pipe wall into the "
                                       "host's faces: a pipe wall touches a face tangentially (along a line, not "
                                       "across a hole): no hex ring, meshed with tetrahedra, flat ones along that "
                                       "line; for a hex ring, move the pipe off the face, at least a tenth of its "
                                       "diameter",
                                       face_list(r.faces))});
    }
    return out;
}

void drop_branches(TubeSearch& tubes, std::vector<RingDrop>& dropped) {
    std::set<int> walls;
    for (const TubeInfo& t : tubes.tubes) walls.insert(t.faces.begin(), t.faces.end());
    for (const RingDrop& d : dropped) walls.insert(d.faces.begin(), d.faces.end());
    for (auto t = tubes.tubes.begin(); t != tubes.tubes.end();) {
        // A ring that stops ends on a cross-section, whatever face lies beyond it.
        const int host = walls.count(t->hosts[0])               ? t->hosts[0]
                         : !t->stop && walls.count(t->hosts[1]) ? t->hosts[1]
                                                                : 0;
        if (host == 0) {
            ++t;
            continue;
        }
        dropped.push_back(drop_of(
            *t, fmt::format("branch ending on the pipe wall face {}", host),
            fmt::format("{} ends on face {}, the wall of another pipe (a T-junction): no plane there for a hex ring to "
                        "end on, so it is meshed with tetrahedra; for a hex ring, end it on a flat face",
                        pipe(*t), host)));
        t = tubes.tubes.erase(t);
    }
}

int tube_without_room(const TubeSearch& tubes, const SizePlan& plan, double thinnest, double thinnest_to_face,
                      RingDrop& drop) {
    if (tubes.tubes.empty()) return -1;
    auto tube = [&](int t) -> const TubeInfo& { return tubes.tubes[static_cast<std::size_t>(t)]; };
    // The thickest ring the distances allow, whatever St was asked for: a ring and its
    // pyramids take kFaceRoom St towards a face and kTubeRoom St between two pipes (sizing's guards).
    const double by_face = plan.dcb / kFaceRoom, by_pipes = plan.dc / kTubeRoom;
    if (by_face <= by_pipes && plan.dcb_tube >= 0 && by_face < thinnest_to_face * tube(plan.dcb_tube).radius_min) {
        const TubeInfo& t = tube(plan.dcb_tube);
        const double r = t.radius_min, dcb = shown(plan.dcb, r);
        drop = drop_of(
            t, fmt::format("{:.2g} r from face {}", dcb / r, plan.dcb_face),
            fmt::format("{} passes {:.3g} from face {} ({:.2g} of its radius {:.3g}){}: a hex ring that fits there "
                        "would be under {:.3g} thick, less than {} of the radius: no hex ring, meshed with "
                        "tetrahedra; for a hex ring, move the pipe at least {:.2g} away from face {}",
                        pipe(t), dcb, plan.dcb_face, dcb / r, r, dcb == 0 ? " - it touches the face" : "",
                        dcb / kFaceRoom, thinnest_to_face, 1.05 * kFaceRoom * thinnest_to_face * r, plan.dcb_face));
        drop.spot = true;
        return plan.dcb_tube;
    }
    if (by_pipes < by_face && plan.dc_tube_a >= 0) {
        const TubeInfo &a = tube(plan.dc_tube_a), &b = tube(plan.dc_tube_b);
        const double r = std::min(a.radius_min, b.radius_min);
        if (by_pipes < thinnest * r) {
            // The one kept faces a tet-meshed wall, like a face: it needs only kFaceRoom St there.
            const auto fits = [&](const TubeInfo& kept) { return plan.dc / kFaceRoom >= thinnest * kept.radius_min; };
            // The smaller wall goes, unless only it would leave room for the other's ring.
            const bool smaller_a = a.radius_min * a.length < b.radius_min * b.length;
            const bool a_goes = smaller_a ? (fits(b) || !fits(a)) : (fits(b) && !fits(a));
            const TubeInfo& gone = a_goes ? a : b;
            const TubeInfo& other = a_goes ? b : a;
            const double dc = shown(plan.dc, r);
            drop = drop_of(
                gone, fmt::format("{:.2g} r from the pipe of wall face {}", dc / r, face_list(other.faces)),
                fmt::format("{} comes within {:.3g} of {} ({:.2g} of the radius {:.3g}){}: hex rings that fit between "
                            "them would be under {:.3g} thick, less than {} of the radius: no hex ring, meshed with "
                            "tetrahedra; for hex rings, keep the walls at least {:.2g} apart",
                            pipe(gone), dc, pipe(other), dc / r, r, dc == 0 ? " - they touch" : "", dc / kTubeRoom,
                            thinnest, 1.05 * kTubeRoom * thinnest * r));
            drop.spot = true;
            return static_cast<int>(&gone - tubes.tubes.data());
        }
    }
    if (std::isfinite(plan.rc))
        for (std::size_t i = 0; i < tubes.tubes.size(); ++i) {
            const TubeInfo& t = tubes.tubes[i];
            if (t.min_curvature_radius != plan.rc) continue;
            const double room = kGuardMargin * (t.min_curvature_radius - t.radius_max);
            if (room >= thinnest * t.radius_min) break;
            drop = drop_of(t, fmt::format("bend of radius {:.3g}", t.min_curvature_radius),
                           fmt::format("{} bends with radius {:.3g} about its centre line, too tight for a hex ring "
                                       "around its radius {:.3g}: no hex ring, meshed with tetrahedra; for a hex "
                                       "ring, bend it with a radius of at least {:.2g}",
                                       pipe(t), t.min_curvature_radius, t.radius_max,
                                       t.radius_max + 1.05 * thinnest * t.radius_min / kGuardMargin));
            return static_cast<int>(i);
        }
    return -1;
}

std::vector<std::string> narrow_gap_warnings(const std::vector<HoleClearance>& holes, std::string& cause) {
    std::vector<std::string> out;
    double narrowest = kThinnestRing;
    cause.clear();
    for (const HoleClearance& h : holes) {
        if (h.distance >= kThinnestRing * h.radius) continue;
        const double distance = shown(h.distance, h.radius);
        if (distance / h.radius < narrowest || cause.empty()) {
            narrowest = distance / h.radius;
            cause = fmt::format("a gap too narrow for sound tets (the hole of faces {} passes {:.3g} from face {}, {:.2g} "
                                "of its radius)",
                                face_list(h.hole_faces), distance, h.face, distance / h.radius);
        }
        out.push_back(fmt::format(
            "the hole of faces {} (no hex ring: meshed with tetrahedra) passes {:.3g} from face {} ({:.2g} of its "
            "radius {:.3g}){}: the tetrahedra in that gap are flat; move the hole at least {:.2g} away from face {} "
            "for sound ones",
            face_list(h.hole_faces), distance, h.face, distance / h.radius, h.radius,
            distance == 0 ? " - it touches the face" : "", 1.05 * kThinnestRing * h.radius, h.face));
    }
    return out;
}

}  // namespace tubemesh::geom
