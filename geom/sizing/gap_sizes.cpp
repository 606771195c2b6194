#include "geom/sizing/gap_sizes.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>

#include "geom/model/model_occt.hpp"
#include "geom/sizing/geometry_diagnosis.hpp"

namespace tubemesh::geom {
namespace {

// Grid points per hole face: enough for a quarter-radius spacing on the longest pipes in the
// generators, a bound on the time a very long hole can cost.
constexpr double kMaxSamples = 1e5;

// A near face, set up once: its projector (over the face's parameter box) and its classifier.
struct Near {
    std::unique_ptr<GeomAPI_ProjectPointOnSurf> project;
    std::unique_ptr<BRepTopAdaptor_FClass2d> inside;
};

Near near_face(const TopoDS_Face& face) {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    Near n{std::make_unique<GeomAPI_ProjectPointOnSurf>(), std::make_unique<BRepTopAdaptor_FClass2d>(face, 1e-9)};
    n.project->Init(BRep_Tool::Surface(face), u0, u1, v0, v1);
    return n;
}

// Length of the face's iso-lines through the middle of its parameter box, sampled.
double iso_length(const BRepAdaptor_Surface& s, bool along_u, double u0, double u1, double v0, double v1) {
    double length = 0;
    gp_Pnt last;
    for (int i = 0; i <= 32; ++i) {
        const double t = i / 32.0;
        const gp_Pnt p = along_u ? s.Value(u0 + t * (u1 - u0), (v0 + v1) / 2) : s.Value((u0 + u1) / 2, v0 + t * (v1 - v0));
        if (i > 0) length += p.Distance(last);
        last = p;
    }
    return length;
}

// Leaves out the sources another one makes redundant: with h_i + g·|x_i - x_j| below h_j (by
// more than rounding), source j never gives the size field's minimum (size_field.hpp), so the
// field is the same without it. Around a wall the gap widens faster than g, so most sources go,
// and the field's queries, whose cost grows with the sources in reach of a large one, stay cheap.
// Only dominating sources in the neighbouring cells of a grid of cell `cell` are looked for.
std::vector<SizeSource> without_redundant(std::vector<SizeSource> sources, double growth, double cell) {
    std::stable_sort(sources.begin(), sources.end(),
                     [](const SizeSource& a, const SizeSource& b) { return a.size < b.size; });
    using Key = std::array<long long, 3>;
    const auto key = [&](const Vec3& p) {
        return Key{static_cast<long long>(std::floor(p.x / cell)), static_cast<long long>(std::floor(p.y / cell)),
                   static_cast<long long>(std::floor(p.z / cell))};
    };
    std::map<Key, std::vector<std::size_t>> grid;  // kept sources per cell
    std::vector<SizeSource> kept;
    for (const SizeSource& s : sources) {
        const Key k = key(s.point);
        bool redundant = false;
        for (long long dx = -1; dx <= 1 && !redundant; ++dx)
            for (long long dy = -1; dy <= 1 && !redundant; ++dy)
                for (long long dz = -1; dz <= 1 && !redundant; ++dz) {
                    const auto it = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
                    if (it == grid.end()) continue;
                    for (std::size_t i : it->second) {
                        const SizeSource& o = kept[i];
                        const double dx2 = o.point.x - s.point.x, dy2 = o.point.y - s.point.y,
                                     dz2 = o.point.z - s.point.z;
                        const double d = std::sqrt(dx2 * dx2 + dy2 * dy2 + dz2 * dz2);
                        if (o.size + growth * d < s.size * (1 - 1e-9)) {
                            redundant = true;
                            break;
                        }
                    }
                }
        if (redundant) continue;
        grid[k].push_back(kept.size());
        kept.push_back(s);
    }
    return kept;
}

}  // namespace

std::vector<SizeSource> gap_size_sources(const Model& model, const std::vector<HoleGroup>& holes, double size,
                                         double growth) {
    std::vector<SizeSource> out;
    for (const HoleGroup& group : holes) {
        if (group.near_faces.empty()) continue;
        std::vector<Near> near;
        for (int g : group.near_faces) near.push_back(near_face(face_of(model, g)));
        for (int f : group.faces) {
            const TopoDS_Face face = face_of(model, f);
            const BRepAdaptor_Surface surface(face);
            const BRepTopAdaptor_FClass2d inside(face, 1e-9);
            double u0, u1, v0, v1;
            BRepTools::UVBounds(face, u0, u1, v0, v1);
            const double lu = iso_length(surface, true, u0, u1, v0, v1), lv = iso_length(surface, false, u0, u1, v0, v1);
            double step = group.radius / 4;
            step = std::max(step, std::sqrt(lu * lv / kMaxSamples));
            const int nu = std::max(1, static_cast<int>(std::ceil(lu / step)));
            const int nv = std::max(1, static_cast<int>(std::ceil(lv / step)));
            for (int i = 0; i <= nu; ++i)
                for (int j = 0; j <= nv; ++j) {
                    const double u = u0 + (u1 - u0) * i / nu, v = v0 + (v1 - v0) * j / nv;
                    if (inside.Perform(gp_Pnt2d(u, v)) == TopAbs_OUT) continue;
                    const gp_Pnt p = surface.Value(u, v);
                    for (const Near& n : near) {
                        GeomAPI_ProjectPointOnSurf& foot = *n.project;
                        foot.Perform(p);
                        if (!foot.IsDone() || foot.NbPoints() == 0 || !(foot.LowerDistance() < size)) continue;
                        double fu, fv;
                        foot.LowerDistanceParameters(fu, fv);
                        if (n.inside->Perform(gp_Pnt2d(fu, fv)) == TopAbs_OUT) continue;
                        const double d = std::max(foot.LowerDistance(), kThinnestRing * group.radius);
                        const gp_Pnt q = foot.NearestPoint();
                        out.push_back({{p.X(), p.Y(), p.Z()}, d});
                        out.push_back({{q.X(), q.Y(), q.Z()}, d});
                    }
                }
        }
    }
    return out.empty() ? out : without_redundant(std::move(out), growth, size / 4);
}

}  // namespace tubemesh::geom
