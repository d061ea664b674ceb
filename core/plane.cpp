#include "core/plane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mc {

bool canonicalize(Plane& p) {
  const double len = norm(p.n);
  if (!(len > 0) || !std::isfinite(len) || !std::isfinite(p.d)) return false;
  p.n = p.n / len;
  p.d /= len;
  const double first = p.n.x != 0 ? p.n.x : (p.n.y != 0 ? p.n.y : p.n.z);
  if (first < 0) {
    p.n = -p.n;
    p.d = -p.d;
  }
  // Avoid signed zeros so equal planes compare bit-equal.
  if (p.n.x == 0) p.n.x = 0;
  if (p.n.y == 0) p.n.y = 0;
  if (p.n.z == 0) p.n.z = 0;
  if (p.d == 0) p.d = 0;
  return true;
}

void BBox::add(const Vec3& p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

std::array<Vec3, 8> BBox::corners() const {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
  return c;
}

bool same_plane_in_box(const Plane& a, const Plane& b, double angle_rad, double dist, const BBox& box) {
  const double c = std::abs(dot(a.n, b.n));
  if (c < std::cos(angle_rad)) return false;
  for (const Vec3& corner : box.corners()) {
    if (std::abs(b.signed_distance(a.project(corner))) > dist) return false;
  }
  return true;
}

PlaneClass classify_plane(const Plane& p, double angle_rad, const Vec3& up) {
  const double nz = std::clamp(std::abs(dot(p.n, up)), 0.0, 1.0);
  const double pitch = std::acos(std::sqrt(std::max(0.0, 1.0 - nz * nz)));  // normal elevation
  if (pitch < angle_rad) return PlaneClass::Vertical;
  if (pitch > M_PI / 2 - angle_rad) return PlaneClass::Horizontal;
  return PlaneClass::Inclined;
}

uint32_t PlaneRegistry::add(Plane p, PlaneOrigin origin) {
  if (!canonicalize(p)) throw std::invalid_argument("degenerate plane normal");
  for (uint32_t i = 0; i < planes_.size(); ++i) {
    if (planes_[i].n == p.n && planes_[i].d == p.d) return i;
  }
  planes_.push_back(p);
  origins_.push_back(origin);
  return static_cast<uint32_t>(planes_.size() - 1);
}

void PlaneRegistry::set_anchor(uint32_t id, const std::array<uint32_t, 3>& via, double d) {
  if (id >= planes_.size()) throw std::out_of_range("set_anchor: no such plane");
  for (uint32_t v : via)
    if (v >= planes_.size() || v == id) throw std::invalid_argument("set_anchor: bad anchor plane");
  if (anchors_.size() < planes_.size()) anchors_.resize(planes_.size(), {UINT32_MAX, UINT32_MAX, UINT32_MAX});
  anchors_[id] = via;
  planes_[id].d = d == 0 ? 0.0 : d;
}

void PlaneRegistry::set_line_anchor(uint32_t id, uint32_t a, uint32_t b, const Plane& line) {
  if (id >= planes_.size() || a >= planes_.size() || b >= planes_.size() || a == id || b == id || a == b)
    throw std::invalid_argument("set_line_anchor: bad planes");
  if (anchor(id)) throw std::invalid_argument("set_line_anchor: the plane is anchored to a point");
  if (line_anchors_.size() < planes_.size()) line_anchors_.resize(planes_.size(), {UINT32_MAX, UINT32_MAX});
  line_anchors_[id] = {a, b};
  planes_[id] = line;
}

size_t PlaneRegistry::num_anchored() const {
  size_t n = 0;
  for (const auto& a : anchors_) n += a[0] != UINT32_MAX;
  return n;
}

uint32_t PlaneRegistry::add_snapped(Plane p, const std::vector<uint32_t>& pool, double angle_rad, double dist,
                                    const BBox& box, PlaneOrigin origin) {
  if (!canonicalize(p)) throw std::invalid_argument("degenerate plane normal");
  for (uint32_t id : pool) {
    if (same_plane_in_box(p, planes_[id], angle_rad, dist, box)) return id;
  }
  return add(p, origin);
}

}  // namespace mc
