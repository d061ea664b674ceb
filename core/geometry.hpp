// The small geometry every stage shares (docs/design.md, "Layers"): a ring's Newell area vector
// and the best-fit plane of points. One implementation each, so the stages agree to the bit.
// The seeded hashing lives in core/hashing.hpp, face triangulation in core/soup.hpp.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace mc {

// Area vector of one ring by Newell's method: direction = the ring's normal (right-hand rule),
// length = twice its area. Computed as a fan from the ring's first vertex, so large
// georeferenced coordinates do not cancel. Zero for fewer than three vertices.
Vec3 ring_area_vector(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& ring);

// The covariance (sum of outer products, not divided) of points about their centroid.
Eigen::Matrix3d centred_covariance(const std::vector<Vec3>& points, Vec3& centroid);

// The principal axes of a covariance: `normal` the unit eigenvector of the smallest eigenvalue
// (the normal of the least-squares plane), `eigenvalues` ascending (to judge degeneracy).
struct PrincipalAxes {
  Vec3 normal;
  Eigen::Vector3d eigenvalues;
};
PrincipalAxes principal_axes(const Eigen::Matrix3d& covariance);

}  // namespace mc
