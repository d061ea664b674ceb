#include "core/geometry.hpp"

#include <Eigen/Eigenvalues>

namespace mc {

Vec3 ring_area_vector(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& ring) {
  Vec3 s;
  if (ring.size() < 3) return s;
  const Vec3 o = vertices[ring[0]];
  for (size_t i = 1; i + 1 < ring.size(); ++i) s += cross(vertices[ring[i]] - o, vertices[ring[i + 1]] - o);
  return s;
}

Eigen::Matrix3d centred_covariance(const std::vector<Vec3>& points, Vec3& centroid) {
  centroid = Vec3{};
  for (const Vec3& p : points) centroid += p;
  if (!points.empty()) centroid = centroid / static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) {
    const Eigen::Vector3d d(p.x - centroid.x, p.y - centroid.y, p.z - centroid.z);
    cov += d * d.transpose();
  }
  return cov;
}

PrincipalAxes principal_axes(const Eigen::Matrix3d& covariance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(covariance);
  const Eigen::Vector3d m = es.eigenvectors().col(0);  // smallest eigenvalue first
  return {Vec3{m(0), m(1), m(2)}, es.eigenvalues()};
}

}  // namespace mc
