#pragma once
// tubemesh::Vec3 to and from OpenCASCADE points and vectors. geom/ only.
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <gp_XYZ.hxx>

#include "engine/mesh/hybrid_mesh.hpp"  // tubemesh::Vec3

namespace tubemesh::geom {

inline gp_Pnt to_pnt(const Vec3& v) { return {v.x, v.y, v.z}; }
inline gp_Vec to_vec(const Vec3& v) { return {v.x, v.y, v.z}; }
inline Vec3 to_vec3(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

}  // namespace tubemesh::geom
