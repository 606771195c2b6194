#pragma once
// Foot points on a tube's wall when the wall is several B-rep faces (a serpentine's straight
// and bent pieces): the nearest face whose parameter ranges contain the foot point.
#include <optional>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "engine/core/vec3.hpp"

namespace tubemesh::sweep {

// Where the last foot point of one circumferential node was found: the next station's node
// starts there, with a hint, and usually stays.
struct WallCursor {
    int face = -1;  // index into the wall's faces; -1: no idea yet
    Uv uv;
};

struct WallFoot {
    Vec3 point;
    double distance = 0;
};

class WallProjection {
public:
    WallProjection() = default;
    // `radius` sets the tolerances: a foot point farther than radius / 20 is not trusted as is.
    WallProjection(std::vector<const SurfaceMap*> faces, double radius);

    // The foot point of p. Tries the cursor's face with its uv as hint first: accepted when the
    // foot lies within the face's parameter ranges and closer than radius / 20. Otherwise the
    // faces in order of their bounding boxes' distance from p, without hints, until one gives
    // such a foot (a foot past a face's end lies on its untrimmed surface only, and global
    // projections are expensive); failing that, the nearest foot of all. Updates the cursor.
    // Throws tubemesh::Error when no face gives a foot point within half the radius.
    WallFoot project(const Vec3& p, WallCursor& cursor) const;

    // Unit normal of the wall where `cursor` (set by project) points: the face's
    // SurfaceMap::normal there. Throws tubemesh::Error at a singular point of the face.
    Vec3 normal(const WallCursor& cursor) const;

private:
    struct Box {
        Vec3 lo, hi;
    };
    std::optional<Projection> try_face(int f, const Vec3& p, std::optional<Uv> hint) const;
    bool acceptable(int f, const Projection& pr) const;

    std::vector<const SurfaceMap*> faces_;
    std::vector<Box> boxes_;  // of a grid of points on each face: a guide to the search order only
    double radius_ = 0;
};

}  // namespace tubemesh::sweep
