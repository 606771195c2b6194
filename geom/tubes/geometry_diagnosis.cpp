#include "geom/tubes/geometry_diagnosis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "engine/core/types.hpp"

namespace tubemesh::geom {

namespace {

std::string face_list(const std::vector<int>& faces) {
    std::string s;
    for (int f : faces) s += (s.empty() ? "" : ", ") + std::to_string(f);
    return s;
}

// A distance as a message gives it: walls that touch measure a few 1e-13 either side of zero,
// and within 1e-6 of the radius the message says they touch, at 0.
double shown(double distance, double radius) { return distance <= 1e-6 * radius ? 0.0 : distance; }

std::string pipe(const TubeSearch& tubes, int t) {
    return fmt::format("pipe {} (wall face {})", t + 1, face_list(tubes.tubes[static_cast<std::size_t>(t)].faces));
}

}  // namespace

void diagnose_faces(const TubeSearch& tubes, int face_count) {
    for (const TubeRejection& r : tubes.rejected) {
        if (r.faces.empty()) continue;
        if (r.loops > 2)
            throw Error(fmt::format(
                "faces {} are pipe walls that meet each other ({} open ends where a pipe has 2): pipes that cross or "
                "touch cannot get hex rings; move them apart (at least a tenth of a diameter between the walls) or "
                "join them into one pipe in the CAD model",
                face_list(r.faces), r.loops));
        // No open end, or one (another pipe's hole) in a group holding most of the solid: the
        // smooth flood from a hole ran along a wall into the host's faces, so a wall is tangent
        // to one of them. A blind hole's group is its wall and bottom only.
        const bool most_faces = r.faces.size() >= 3 && 2 * r.faces.size() > static_cast<std::size_t>(face_count);
        if (r.loops == 0 || (r.loops == 1 && most_faces))
            throw Error(fmt::format(
                "faces {} join smoothly into one group that runs from a pipe wall into the host's faces: a pipe "
                "wall touches a face tangentially (along a line, not across a hole); move the pipe off the face, at "
                "least a tenth of its diameter",
                face_list(r.faces)));
    }
}

void diagnose_clearances(const TubeSearch& tubes, const SizePlan& plan) {
    if (tubes.tubes.empty()) return;
    auto radius = [&](int t) { return tubes.tubes[static_cast<std::size_t>(t)].radius_min; };
    // The thickest ring the distances allow, whatever St was asked for: a ring and its
    // pyramids take kFaceRoom St towards a face and kTubeRoom St between two pipes (sizing's guards).
    const double by_face = plan.dcb / kFaceRoom, by_pipes = plan.dc / kTubeRoom;
    const double thinnest = plan.local_ring ? kThinnestLocalRing : kThinnestRing;
    // The distance advised: the limit rounded up (0.064 r with the local ring).
    const double face_advice = plan.local_ring ? 0.1 : 0.2;
    if (by_face <= by_pipes && plan.dcb_tube >= 0 && by_face < thinnest * radius(plan.dcb_tube)) {
        const double r = radius(plan.dcb_tube);
        const double dcb = shown(plan.dcb, r);
        throw Error(fmt::format(
            "{} passes {:.3g} from face {} ({:.2g} of its radius {:.3g}){}: a hex ring that fits there would be "
            "under {:.3g} thick, less than {} of the radius, and take millions of elements; move the pipe at least "
            "{:.3g} away from face {}",
            pipe(tubes, plan.dcb_tube), dcb, plan.dcb_face, dcb / r, r, dcb == 0 ? " - it touches the face" : "",
            dcb / kFaceRoom, thinnest, face_advice * r, plan.dcb_face));
    }
    if (by_pipes < by_face && plan.dc_tube_a >= 0) {
        const double r = std::min(radius(plan.dc_tube_a), radius(plan.dc_tube_b));
        const double dc = shown(plan.dc, r);
        if (by_pipes < kThinnestRing * r)
            throw Error(fmt::format(
                "{} and {} come within {:.3g} of each other ({:.2g} of the radius {:.3g}){}: hex rings that fit "
                "between them would be under {:.3g} thick, less than {} of the radius, and take millions of "
                "elements; keep the walls at least {:.3g} apart",
                pipe(tubes, plan.dc_tube_a), pipe(tubes, plan.dc_tube_b), dc, dc / r, r,
                dc == 0 ? " - they touch" : "", dc / kTubeRoom, kThinnestRing, 0.25 * r));
    }
}

void diagnose_hole_clearances(const std::vector<HoleClearance>& holes) {
    for (const HoleClearance& h : holes) {
        if (h.distance >= kThinnestRing * h.radius) continue;
        const double distance = shown(h.distance, h.radius);
        throw Error(fmt::format(
            "the hole of faces {} (not a tube: meshed with tetrahedra) passes {:.3g} from face {} ({:.2g} of its radius "
            "{:.3g}){}: the tetrahedra in that gap would be slivers; move the hole at least {:.3g} away from face {}",
            face_list(h.hole_faces), distance, h.face, distance / h.radius, h.radius,
            distance == 0 ? " - it touches the face" : "", 0.2 * h.radius, h.face));
    }
}

}  // namespace tubemesh::geom
