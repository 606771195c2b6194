#pragma once
// Rotation-minimising frames along a tube's centre line: the frames the sweep places its
// cross-sections in, so no twist builds up along bends and serpentine paths.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <span>
#include <vector>

namespace tubemesh {

struct Frame {
    Eigen::Vector3d tangent;  // unit, along the centre line
    Eigen::Vector3d normal;   // unit, orthogonal to tangent; angle 0 of the cross-section
    Eigen::Vector3d binormal; // tangent x normal; angle pi/2
};

// Double-reflection method (Wang, Jüttler, Zheng, Liu 2008): each frame is the previous one
// reflected twice, which approximates the rotation-minimising (Bishop) frame to fourth order
// per step. `initial_normal` is projected onto the plane normal to the first tangent.
// Throws tubemesh::Error for fewer than two stations, zero tangents, repeated stations or an
// initial normal parallel to the first tangent.
std::vector<Frame> rotation_minimizing_frames(std::span<const Eigen::Vector3d> centres,
                                              std::span<const Eigen::Vector3d> tangents,
                                              const Eigen::Vector3d& initial_normal);

// A unit vector orthogonal to `t`, chosen by a fixed rule so callers without a preferred
// direction get a reproducible one.
Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& t);

// Signed angle from a to b around the unit axis (both projected onto the plane normal to it).
double signed_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& axis);

}  // namespace tubemesh
