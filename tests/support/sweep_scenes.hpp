#pragma once
// Synthetic tubes for the sweep's tests: a centre line of straight and circular pieces, one
// wall face per piece (cylinder or torus), host faces (planes, convex or concave cylinders)
// met square or at an angle, and the TubeData geom would hand over: stations about St apart by
// arc length with references following one generator line, and end rings on the wall/host
// intersection spaced by arc length with node 0 on that generator line.
#include <memory>
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_surfaces.hpp"

namespace tubemesh::sweep_testing {

// A centre line from a start point, direction and reference; arcs turn the reference with
// the tangent (parallel transport: for circular pieces that is the rotation-minimising frame).
class Path {
public:
    Path(const V& start, const V& tangent, const V& reference);

    void straight(double length);
    // Bend of radius R by `angle` towards cos(plane)·reference + sin(plane)·(tangent x reference).
    void arc(double R, double angle, double plane = 0);

    double length() const { return pieces_.empty() ? 0 : pieces_.back().s0 + pieces_.back().length; }
    // Beyond either end the path goes on straight.
    V point(double s) const;
    V tangent(double s) const;
    V reference(double s) const;

    struct Piece {
        bool arc = false;
        double s0 = 0, length = 0;
        V start, tangent, reference;  // at the piece's start
        V centre = V::Zero(), axis = V::Zero();  // arcs: the bend's centre and axis (tangent x towards centre)
        double R = 0;
    };
    const std::vector<Piece>& pieces() const { return pieces_; }

private:
    const Piece& piece_at(double s) const;
    V end_point_, end_tangent_, end_reference_;
    std::vector<Piece> pieces_;
};

struct TubeSpec {
    double radius = 0.02;
    double sweep_size = 0.04;  // St: the stations' spacing, like geom's
    // The path runs `lead` past each host: the tube proper is [lead, length - lead].
    double lead = 0.2;
    index_t host1 = 0, host2 = 0;
    bool zero_reference = false;  // give no references (the sweep falls back on its frames)
    bool left_handed = false;     // rings turn left-handed about the tangent
    bool clamped_walls = false;   // wall faces project into their ranges (bounded B-splines)
    int n = 0;                    // 0: circumferential_count(radius, sweep_size)
};

class Scene {
public:
    // Hosts; each returns the face id. `normal` is the solid's outward normal at `at`.
    index_t plane(const V& at, const V& normal);
    // Cylinder of radius R through `at` with outward normal `normal` there and axis along
    // `axis` (orthogonal to normal): convex holds the solid inside (a journal), otherwise
    // outside (a bore).
    index_t cylinder(const V& at, const V& normal, const V& axis, double R, bool convex);

    // A tube along `path` from host1 (crossed near s = lead) to host2 (near length - lead).
    // Returns its index.
    std::size_t tube(const Path& path, const TubeSpec& spec);

    std::vector<TubeData> tubes;
    std::vector<Path> paths;
    std::vector<TubeSpec> specs;
    const TestSurface& surface(index_t id) const;
    SurfaceLookup lookup() const;
    // Default options with each tube's St from its spec. Call lookup() on the final Scene: the
    // lookup refers to it.
    SweepOptions options() const;

private:
    index_t add(std::unique_ptr<TestSurface> s);
    std::vector<std::unique_ptr<TestSurface>> surfaces_;
};

// A straight pipe square through a slab between z = 0 and z = thickness.
Scene straight_scene(double radius, double sweep_size, double thickness);

// A 180-degree bend entering and leaving one plane face (a U-tube): bend radius R.
Scene u_bend_scene(double radius, double sweep_size, double R, bool zero_reference);

// Serpentine in a plane: `legs` straight legs of length `leg` joined by half-circle bends of
// radius R, entering the face x = 0 and leaving by x = 0 (even legs) or x = leg (odd).
Path serpentine_path(int legs, double leg, double R, double lead, const V& origin = V::Zero());
Scene serpentine_scene(double radius, double sweep_size, int legs, double leg, double R, bool zero_reference,
                       bool clamped_walls = false);

// The crankshaft's oil hole: a straight hole through a journal of radius R (convex cylinder),
// its axis meeting the journal's surface at `angle` from the surface normal, entering and
// leaving the journal face. `through_axis`: the hole crosses the journal's axis, inclined
// along it (geom's paper-ex3 builder, 30 degrees), so the slant runs along the journal's
// straight lines; otherwise it passes the axis at a distance in a cross-section, slanting
// where the journal curves.
Scene oil_hole_scene(double radius, double sweep_size, double R, double angle, bool through_axis);

// A straight pipe leaving a plane at `angle1` from its normal and ending on a concave
// cylinder (a bore of radius R) at `angle2`.
Scene oblique_scene(double radius, double sweep_size, double angle1, double angle2, double R);

}  // namespace tubemesh::sweep_testing
