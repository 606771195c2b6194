#pragma once
// The one vector type of the engine: a point or a direction in double precision. Its
// arithmetic is in vec3_ops.hpp.

namespace tubemesh {

struct Vec3 {
    double x, y, z;
};

}  // namespace tubemesh
