#include "geom/sizing/ring_room.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <Precision.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <set>

#include "engine/core/vec3_ops.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/sizing/sizing.hpp"

namespace tubemesh::geom {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The fan of rays per direction: this far to either side, around the axis and along it.
constexpr double kFanDegrees = 25;

// The points' arc lengths and frames: tangent by central differences, u carried along by
// projection (no twist builds up along a straight or planar line).
struct Frames {
    std::vector<double> s;
    std::vector<Vec3> t, u;
};

Vec3 unit(const Vec3& v) { return (1.0 / norm(v)) * v; }

Frames frames(const std::vector<Vec3>& line) {
    Frames f;
    const std::size_t n = line.size();
    f.s.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) f.s[i] = f.s[i - 1] + norm(line[i] - line[i - 1]);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 a = line[i == 0 ? 0 : i - 1], b = line[std::min(i + 1, n - 1)];
        f.t.push_back(unit(b - a));
    }
    for (std::size_t i = 0; i < n; ++i) {
        Vec3 u;
        if (i == 0) {
            const Vec3& t = f.t[0];
            const Vec3 axis = std::abs(t.x) <= std::abs(t.y) && std::abs(t.x) <= std::abs(t.z) ? Vec3{1, 0, 0}
                              : std::abs(t.y) <= std::abs(t.z)                                ? Vec3{0, 1, 0}
                                                                                               : Vec3{0, 0, 1};
            u = axis - dot(axis, t) * t;
        } else {
            u = f.u[i - 1] - dot(f.u[i - 1], f.t[i]) * f.t[i];
            if (norm(u) < 1e-6) u = cross(f.t[i], cross(f.u[i - 1], f.t[i]));
        }
        f.u.push_back(unit(u));
    }
    return f;
}

// Distance along the unit ray o + w·e to the capsule of radius r around segment a-b; +inf when
// it misses or only behind o.
double ray_capsule(const Vec3& o, const Vec3& e, const Vec3& a, const Vec3& b, double r) {
    const Vec3 ba = b - a, oa = o - a;
    const double baba = dot(ba, ba), bard = dot(ba, e), baoa = dot(ba, oa), rdoa = dot(e, oa), oaoa = dot(oa, oa);
    const double qa = baba - bard * bard, qb = baba * rdoa - baoa * bard, qc = baba * oaoa - baoa * baoa - r * r * baba;
    if (qa > 1e-14 * baba) {
        const double h = qb * qb - qa * qc;
        if (h < 0) return kInf;
        const double w = (-qb - std::sqrt(h)) / qa;
        const double y = baoa + w * bard;
        if (y > 0 && y < baba) return w >= 0 ? w : kInf;
    }
    // The end spheres.
    double best = kInf;
    for (const Vec3& c : {a, b}) {
        const Vec3 oc = o - c;
        const double hb = dot(e, oc), hc = dot(oc, oc) - r * r, h = hb * hb - hc;
        if (h < 0) continue;
        const double w = -hb - std::sqrt(h);
        if (w >= 0) best = std::min(best, w);
    }
    return best;
}

// Boxes of runs of a polyline's segments, for culling.
struct Run {
    std::size_t first, last;  // segments [first, last)
    Vec3 lo, hi;
};
constexpr std::size_t kRun = 8;

std::vector<Run> runs(const std::vector<Vec3>& line) {
    std::vector<Run> out;
    if (line.size() < 2) return out;
    for (std::size_t first = 0; first + 1 < line.size(); first += kRun) {
        Run r{first, std::min(first + kRun, line.size() - 1), line[first], line[first]};
        for (std::size_t i = first; i <= r.last; ++i) {
            r.lo = {std::min(r.lo.x, line[i].x), std::min(r.lo.y, line[i].y), std::min(r.lo.z, line[i].z)};
            r.hi = {std::max(r.hi.x, line[i].x), std::max(r.hi.y, line[i].y), std::max(r.hi.z, line[i].z)};
        }
        out.push_back(r);
    }
    return out;
}

double point_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const double dx = std::max({0.0, lo.x - p.x, p.x - hi.x});
    const double dy = std::max({0.0, lo.y - p.y, p.y - hi.y});
    const double dz = std::max({0.0, lo.z - p.z, p.z - hi.z});
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// A face other than tube walls, with its box and (built when first needed) its intersector.
struct Obstacle {
    int face = 0;
    Vec3 lo, hi;
    std::unique_ptr<IntCurvesFace_Intersector> cut;
};

// Nearest hit of the ray o + w·e, 0 <= w <= reach, on the face; +inf when none.
double ray_face(Obstacle& f, const Model& model, const Vec3& o, const Vec3& e, double reach) {
    if (!f.cut) f.cut = std::make_unique<IntCurvesFace_Intersector>(face_of(model, f.face), Precision::Confusion());
    f.cut->Perform(gp_Lin(gp_Pnt(o.x, o.y, o.z), gp_Dir(e.x, e.y, e.z)), 0.0, reach);
    double best = kInf;
    if (!f.cut->IsDone()) return best;
    for (int k = 1; k <= f.cut->NbPnt(); ++k) {
        const double w = f.cut->WParameter(k);
        if (w >= 0) best = std::min(best, w);
    }
    return best;
}

// The fan of rays around direction d (unit, ⊥ t): rotated about t and tilted along t.
std::vector<Vec3> fan(const Vec3& d, const Vec3& t) {
    const double a = kFanDegrees * std::numbers::pi / 180;
    const Vec3 side = cross(t, d);
    std::vector<Vec3> out;
    for (double around : {0.0, -a, a})
        for (double along : {0.0, -a, a}) {
            const Vec3 in_plane = std::cos(around) * d + std::sin(around) * side;
            out.push_back(unit(std::cos(along) * in_plane + std::sin(along) * t));
        }
    return out;
}

// Lipschitz grading: each value at most its neighbours' plus growth times the distance, along
// s (per direction) and around (per point, periodic), by forward and backward passes.
void grade(std::vector<double>& t, const std::vector<double>& s, int d, double arc, double growth) {
    const std::size_t n = s.size(), dd = static_cast<std::size_t>(d);
    for (std::size_t k = 0; k < dd; ++k) {
        for (std::size_t i = 1; i < n; ++i)
            t[i * dd + k] = std::min(t[i * dd + k], t[(i - 1) * dd + k] + growth * (s[i] - s[i - 1]));
        for (std::size_t i = n - 1; i-- > 0;)
            t[i * dd + k] = std::min(t[i * dd + k], t[(i + 1) * dd + k] + growth * (s[i + 1] - s[i]));
    }
    for (std::size_t i = 0; i < n; ++i) {
        double* row = t.data() + i * dd;
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t k = 0; k < dd; ++k) row[(k + 1) % dd] = std::min(row[(k + 1) % dd], row[k] + growth * arc);
            for (std::size_t k = dd; k-- > 0;) row[k] = std::min(row[k], row[(k + 1) % dd] + growth * arc);
        }
    }
}

RingRoom tube_room(const Model& model, const std::vector<TubeInfo>& tubes, std::size_t which,
                   std::vector<Obstacle>& faces, const std::vector<std::vector<Run>>& tube_runs, double st) {
    const TubeInfo& tube = tubes[which];
    const std::vector<Vec3>& line = tube.centre_line;
    RingRoom room;
    if (line.size() < 2) return room;
    const double r = tube.radius_max;
    const double face_reach = kFaceRoom * st / kGuardMargin, tube_reach = kTubeRoom * st / kGuardMargin;
    // Own segments this close along the line are the wall the ray leaves, not another run.
    const double own_skip = std::numbers::pi * (r + tube_reach);
    const Frames f = frames(line);
    const std::size_t n = line.size();
    const int dirs = kRoomDirections;
    std::vector<double> thick(n * dirs, st);
    bool thin = false;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& c = line[i];
        const Vec3 v = cross(f.t[i], f.u[i]);
        std::vector<Obstacle*> near_faces;
        for (Obstacle& o : faces)
            if (o.face != tube.hosts[0] && o.face != tube.hosts[1] && point_box(c, o.lo, o.hi) <= r + face_reach)
                near_faces.push_back(&o);
        struct Segment {
            Vec3 a, b;
            double r;
        };
        std::vector<Segment> near_segments;
        for (std::size_t j = 0; j < tubes.size(); ++j) {
            const double rj = tubes[j].radius_max;
            for (const Run& run : tube_runs[j]) {
                if (point_box(c, run.lo, run.hi) > r + tube_reach + rj) continue;
                for (std::size_t k = run.first; k < run.last; ++k) {
                    const Vec3 &a = tubes[j].centre_line[k], &b = tubes[j].centre_line[k + 1];
                    if (j == which) {
                        // Arc distance from point i to the segment k..k+1 of its own line.
                        const double gap = f.s[k + 1] < f.s[i] ? f.s[i] - f.s[k + 1] : f.s[k] > f.s[i] ? f.s[k] - f.s[i] : 0.0;
                        if (gap < own_skip) continue;
                    }
                    near_segments.push_back({a, b, rj});
                }
            }
        }
        if (near_faces.empty() && near_segments.empty()) continue;
        for (int k = 0; k < dirs; ++k) {
            const double phi = 2 * std::numbers::pi * k / dirs;
            const Vec3 d = std::cos(phi) * f.u[i] + std::sin(phi) * v;
            const Vec3 origin = c + r * d;
            double to_face = kInf, to_tube = kInf;
            for (const Vec3& e : fan(d, f.t[i])) {
                for (Obstacle* o : near_faces) to_face = std::min(to_face, ray_face(*o, model, origin, e, face_reach));
                for (const Segment& sg : near_segments)
                    to_tube = std::min(to_tube, ray_capsule(origin, e, sg.a, sg.b, sg.r));
            }
            const double allowed = kGuardMargin * std::min(to_face / kFaceRoom, to_tube / kTubeRoom);
            if (allowed < st) {
                thick[i * dirs + k] = allowed;
                thin = true;
            }
        }
    }
    if (!thin) return room;
    grade(thick, f.s, dirs, (r + st) * 2 * std::numbers::pi / dirs, kRoomGrowth);
    room.directions = dirs;
    room.s = f.s;
    room.tangent = f.t;
    room.u = f.u;
    room.thickness = std::move(thick);
    return room;
}

}  // namespace

std::vector<RingRoom> ring_rooms(const Model& model, const std::vector<TubeInfo>& tubes, double sweep_size) {
    std::set<int> walls;
    for (const TubeInfo& t : tubes) walls.insert(t.faces.begin(), t.faces.end());
    std::vector<Obstacle> faces;
    for (int id = 1; id <= model.face_count(); ++id) {
        if (walls.count(id)) continue;
        Bnd_Box box;
        BRepBndLib::Add(face_of(model, id), box);
        if (box.IsVoid()) continue;
        Obstacle o;
        o.face = id;
        box.Get(o.lo.x, o.lo.y, o.lo.z, o.hi.x, o.hi.y, o.hi.z);
        faces.push_back(std::move(o));
    }
    std::vector<std::vector<Run>> tube_runs;
    for (const TubeInfo& t : tubes) tube_runs.push_back(runs(t.centre_line));
    std::vector<RingRoom> out;
    for (std::size_t i = 0; i < tubes.size(); ++i) out.push_back(tube_room(model, tubes, i, faces, tube_runs, sweep_size));
    return out;
}

}  // namespace tubemesh::geom
