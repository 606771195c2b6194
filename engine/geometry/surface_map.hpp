#pragma once
// A B-rep face's parametrisation as the engine sees it: uv -> xyz with derivatives, xyz -> uv
// projection, its parameter ranges and its trimming loops. geom/ implements it over
// OpenCASCADE (geom/model/surface_map_occt.hpp); engine tests can implement it analytically.
//
// Every const member must be safe to call from several threads at once: the engine meshes
// faces in parallel and may project into one face from several tasks.
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"  // Vec3

namespace tubemesh {

struct Uv {
    double u = 0, v = 0;
};

// One parameter direction of the face.
struct ParamRange {
    double lo = 0, hi = 0;  // the face's extent in this parameter
    // The face wraps around in this parameter (a full cylinder): hi - lo is one period and
    // the two ends meet at a seam edge, which the trimming loops cross twice.
    bool closed = false;
    // > 0 when the underlying surface is periodic in this parameter (then u and u + period
    // are the same point), whether or not the face spans a whole period.
    double period = 0;
};

struct SurfaceDerivatives {
    Vec3 point;
    Vec3 du;  // dS/du
    Vec3 dv;  // dS/dv
};

struct Projection {
    bool ok = false;  // false when the projection found no foot point (see project())
    Uv uv;            // normalised into the face's ranges
    Vec3 point;       // S(uv)
    double distance = 0;
};

// One traversal of a B-rep edge by a loop. A seam edge is used twice by its face, once in each
// direction, with a different uv curve each time.
struct EdgeUse {
    index_t edge = 0;     // B-rep edge id
    bool forward = true;  // the loop runs along the edge's parameter (false: against it)
};

// A trimming loop in the face's uv space, with material on the left (outer loops turn
// counter-clockwise, holes clockwise) for the face's natural orientation (du x dv).
struct TrimLoop {
    std::vector<EdgeUse> edges;           // in loop order
    std::vector<std::size_t> edge_begin;  // index into uv where each edge use starts
    std::vector<Uv> uv;                   // closed polyline, first point not repeated
};

class SurfaceMap {
public:
    virtual ~SurfaceMap() = default;

    virtual index_t face() const = 0;  // B-rep face id
    virtual ParamRange u_range() const = 0;
    virtual ParamRange v_range() const = 0;
    // True when the outward normal of the solid is -(du x dv) here: the face is used reversed.
    virtual bool reversed() const = 0;

    virtual Vec3 point(Uv uv) const = 0;
    virtual SurfaceDerivatives derivatives(Uv uv) const = 0;

    // Nearest point to p on the face's surface, untrimmed: it may lie outside the face's loops,
    // and the caller decides what that means. `hint` (a nearby uv, e.g. a neighbour's) makes
    // the search local and fast; without one it starts from the whole face. The result is
    // normalised into the face's ranges (periodic twins one period away are folded back). `ok`
    // is false only when no foot point was found; where it is not unique (the exact axis point
    // of a cylinder or torus) one of them is returned.
    virtual Projection project(const Vec3& p, std::optional<Uv> hint) const = 0;

    // uv of the point at curve parameter t of an edge use of this face, by the edge's uv curve
    // (exact, and on a seam it picks the side the use runs along). Throws tubemesh::Error when
    // the edge is not on this face.
    virtual Uv edge_uv(EdgeUse use, double t) const = 0;

    // The face's trimming loops, outer loop first, then the holes. Each edge use is sampled at
    // even steps of its parameter, at least 4 and enough for steps of at most `max_step` in
    // space (0: 4 per edge). Degenerate edges (a cone's apex) are included: they are a stretch
    // of the uv boundary though they have no length.
    virtual std::vector<TrimLoop> trimming_loops(double max_step) const = 0;

    // Unit outward normal of the solid at uv (zero at a singular point).
    Vec3 normal(Uv uv) const {
        const SurfaceDerivatives d = derivatives(uv);
        Vec3 n{d.du.y * d.dv.z - d.du.z * d.dv.y, d.du.z * d.dv.x - d.du.x * d.dv.z, d.du.x * d.dv.y - d.du.y * d.dv.x};
        const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (len == 0) return {0, 0, 0};
        const double s = (reversed() ? -1.0 : 1.0) / len;
        return {n.x * s, n.y * s, n.z * s};
    }
};

}  // namespace tubemesh
