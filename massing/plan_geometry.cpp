#include "massing/plan_geometry.hpp"

#include <cpl_error.h>
#include <ogr_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/hull.hpp"

namespace mc::massing {

using mc::io::MultiPolygon2;
using mc::io::Polygon2;
using mc::io::Ring2;

namespace {

double cross2(const Pt& o, const Pt& a, const Pt& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

using mc::io::to_ogr;

Polygon2 from_ogr(const OGRPolygon& p) {
  Polygon2 out;
  auto ring = [](const OGRLinearRing* r) {
    Ring2 x;
    const int n = r->getNumPoints();
    for (int i = 0; i + 1 < n; ++i) x.push_back({r->getX(i), r->getY(i)});
    return x;
  };
  if (const OGRLinearRing* ext = p.getExteriorRing()) out.push_back(ring(ext));
  for (int i = 0; i < p.getNumInteriorRings(); ++i) out.push_back(ring(p.getInteriorRing(i)));
  return out;
}

void collect(const OGRGeometry* g, MultiPolygon2& out) {
  if (!g) return;
  const OGRwkbGeometryType t = wkbFlatten(g->getGeometryType());
  if (t == wkbPolygon) {
    out.push_back(from_ogr(*g->toPolygon()));
  } else if (t == wkbMultiPolygon || t == wkbGeometryCollection) {
    const auto* c = g->toGeometryCollection();
    for (int i = 0; i < c->getNumGeometries(); ++i) collect(c->getGeometryRef(i), out);
  }
}

}  // namespace

double snap(double v) { return std::round(v * 1e6) / 1e6; }

double ring_signed_area(const Ring2& r) {
  double s = 0;
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const Pt& a = r[i];
    const Pt& b = r[(i + 1) % n];
    s += a[0] * b[1] - b[0] * a[1];
  }
  return s / 2;
}

double polygon_area(const Polygon2& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) a += (i == 0 ? 1 : -1) * std::abs(ring_signed_area(p[i]));
  return a;
}

double multipolygon_area(const MultiPolygon2& m) {
  double a = 0;
  for (const auto& p : m) a += polygon_area(p);
  return a;
}

PlanExtent plan_extent(const Ring2& hull) {
  PlanExtent e;
  if (hull.size() < 3) return e;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Pt& a = hull[i];
    const Pt& b = hull[(i + 1) % hull.size()];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (len <= 0) continue;
    double far = 0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Pt& q : hull) {
      far = std::max(far, std::abs(cross2(a, b, q)) / len);
      const double t = ((q[0] - a[0]) * (b[0] - a[0]) + (q[1] - a[1]) * (b[1] - a[1])) / len;
      lo = std::min(lo, t), hi = std::max(hi, t);
    }
    if (far < best) best = far, e.length = hi - lo;
  }
  e.width = std::isfinite(best) ? best : 0;
  return e;
}

Ring2 outer_hull(const MultiPolygon2& m) {
  std::vector<Pt> outer;
  for (const auto& poly : m)
    if (!poly.empty()) outer.insert(outer.end(), poly[0].begin(), poly[0].end());
  return mc::convex_hull_2d(outer);
}

MultiPolygon2 union_of(const std::vector<Polygon2>& polys, bool& ok) {
  // Invalid footprints are expected (faces projected edge-on) and repaired below: GEOS's notices
  // about them would only be noise on the user's stderr. The handler stack is per thread.
  struct QuietGdal {
    QuietGdal() { CPLPushErrorHandler(CPLQuietErrorHandler); }
    ~QuietGdal() { CPLPopErrorHandler(); }
  } quiet;
  OGRMultiPolygon mp;
  for (const auto& p : polys) {
    OGRPolygon g = to_ogr(p);
    if (g.IsEmpty()) continue;
    if (!g.IsValid()) {
      std::unique_ptr<OGRGeometry> fixed(g.Buffer(0));
      MultiPolygon2 parts;
      collect(fixed.get(), parts);
      for (const auto& q : parts) {
        OGRPolygon h = to_ogr(q);
        if (!h.IsEmpty()) mp.addGeometry(&h);
      }
      continue;
    }
    mp.addGeometry(&g);
  }
  MultiPolygon2 out;
  ok = true;
  if (mp.IsEmpty()) return out;
  std::unique_ptr<OGRGeometry> u(mp.UnionCascaded());
  if (!u) {
    ok = false;
    return out;
  }
  collect(u.get(), out);
  // Canonical order (GEOS's output order is deterministic, but make it independent of it).
  for (auto& poly : out)
    for (auto& r : poly) {
      if (r.empty()) continue;
      std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
    }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace mc::massing
