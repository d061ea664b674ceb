// The small geometry every stage shares (docs/design.md, "Layers"): a ring's Newell area vector,
// the best-fit plane of points and the closest point on a triangle. One implementation each, so the stages
// agree to the bit. The seeded hashing lives in core/hashing.hpp, face triangulation in core/soup.hpp.
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

// The closest point to p on triangle abc (Ericson, Real-Time Collision Detection, §5.1.5): by
// the Voronoi region of p, in doubles. Inline: the Hausdorff distances call it per candidate.
inline Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace mc
