#include "pipeline/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/hull.hpp"

namespace mc::pipeline {

namespace {

// The first vertex any face uses: a local origin near the geometry.
std::optional<Vec3> local_origin(const PolygonMesh& m) {
  for (const Polygon& f : m.faces)
    for (const auto& ring : f.rings)
      for (uint32_t v : ring)
        if (v < m.vertices.size()) return m.vertices[v];
  return std::nullopt;
}

template <class F>
void for_used_vertices(const PolygonMesh& m, F&& f) {
  for (const Polygon& p : m.faces)
    for (const auto& ring : p.rings)
      for (uint32_t v : ring)
        if (v < m.vertices.size()) f(m.vertices[v]);
}

// Accumulates volume and first moments, relative to origin o.
void accumulate(const PolygonMesh& m, const Vec3& o, double& vol, Vec3& moment) {
  for (const Polygon& f : m.faces) {
    for (const auto& ring : f.rings) {
      if (ring.size() < 3) continue;
      bool ok = true;
      for (uint32_t v : ring) ok = ok && v < m.vertices.size();
      if (!ok) continue;
      const Vec3 a = m.vertices[ring[0]] - o;
      for (size_t i = 1; i + 1 < ring.size(); ++i) {
        const Vec3 b = m.vertices[ring[i]] - o, c = m.vertices[ring[i + 1]] - o;
        const double v = dot(a, cross(b, c)) / 6.0;
        vol += v;
        moment += (a + b + c) * (v / 4.0);
      }
    }
  }
}

double ring_area_xy(const PolygonMesh& m, const std::vector<uint32_t>& ring, const Vec3& o) {
  double s = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const uint32_t a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a >= m.vertices.size() || b >= m.vertices.size()) return 0;
    const Vec3 p = m.vertices[a] - o, q = m.vertices[b] - o;
    s += p.x * q.y - q.x * p.y;
  }
  return std::abs(s) / 2;
}

}  // namespace

VolumeCentroid volume_centroid(const std::vector<PolygonMesh>& ms) {
  std::optional<Vec3> o;
  for (const auto& m : ms)
    if (!o) o = local_origin(m);
  VolumeCentroid r;
  if (!o) return r;
  Vec3 moment;
  for (const auto& m : ms) accumulate(m, *o, r.volume, moment);
  r.centroid = r.volume != 0 ? *o + moment / r.volume : *o;
  return r;
}

VolumeCentroid volume_centroid(const PolygonMesh& m) { return volume_centroid(std::vector<PolygonMesh>{m}); }

double projected_area(const PolygonMesh& m, const Polygon& p) {
  if (p.rings.empty() || p.rings[0].empty() || p.rings[0][0] >= m.vertices.size()) return 0;
  const Vec3 o = m.vertices[p.rings[0][0]];
  double a = ring_area_xy(m, p.rings[0], o);
  for (size_t r = 1; r < p.rings.size(); ++r) a -= ring_area_xy(m, p.rings[r], o);
  return std::max(a, 0.0);
}

double hull_area_2d(const std::vector<Vec3>& points) {
  if (points.size() < 3) return 0;
  const Vec3 o = points[0];
  std::vector<std::array<double, 2>> p;
  p.reserve(points.size());
  for (const Vec3& v : points) p.push_back({v.x - o.x, v.y - o.y});
  const auto h = convex_hull_2d(std::move(p));
  if (h.size() < 3) return 0;
  double s = 0;
  for (size_t i = 0; i < h.size(); ++i) {
    const auto& a = h[i];
    const auto& b = h[(i + 1) % h.size()];
    s += a[0] * b[1] - b[0] * a[1];
  }
  return std::abs(s) / 2;
}

Footprint footprint(const PolygonMesh& input) {
  Footprint fp;
  int32_t ground = -1;
  for (size_t i = 0; i < input.semantic_labels.size(); ++i)
    if (input.semantic_labels[i] == "GroundSurface") ground = static_cast<int32_t>(i);
  if (ground >= 0) {
    for (const Polygon& f : input.faces)
      if (f.semantic == ground) fp.area += projected_area(input, f);
    fp.method = "ground";
    if (fp.area > 0) return fp;
  }
  std::vector<Vec3> pts;
  for_used_vertices(input, [&](const Vec3& v) { pts.push_back(v); });
  fp.area = hull_area_2d(pts);
  fp.method = "hull";
  return fp;
}

std::optional<double> height(const PolygonMesh& m) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for_used_vertices(m, [&](const Vec3& v) {
    lo = std::min(lo, v.z);
    hi = std::max(hi, v.z);
  });
  if (!(lo <= hi)) return std::nullopt;
  return hi - lo;
}

std::optional<Vec3> bbox_centre(const PolygonMesh& m) {
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  bool any = false;
  for_used_vertices(m, [&](const Vec3& v) {
    any = true;
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  });
  if (!any) return std::nullopt;
  return (lo + hi) * 0.5;
}

}  // namespace mc::pipeline
