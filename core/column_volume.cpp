#include "core/column_volume.hpp"

#include "core/stamped_table.hpp"

#include <algorithm>
#include <cmath>

namespace mc {

double polytope_volume(const ConvexPolytope& p) {
  if (p.empty()) return 0;
  const Vec3 ref = p.points.front();
  double six = 0;
  for (size_t f = 0; f < p.face_count(); ++f) {
    const uint32_t b = p.face_begin(f), e = p.ends[f];
    for (uint32_t i = b + 1; i + 1 < e; ++i)
      six += dot(p.points[b] - ref, cross(p.points[i] - ref, p.points[i + 1] - ref));
  }
  return six / 6;
}

namespace {

// Each point's distance to the plane into `dist` (within eps: 0), and the polytope's side: -1
// every vertex on the kept side (or on the plane); +1 none strictly on the kept side (the
// polytope lies on or beyond the plane); 0 the plane cuts it. The distances serve the clipping.
int polytope_side(const ConvexPolytope& p, const Plane& pl, double eps, std::vector<double>& dist) {
  bool below = false, above = false;
  dist.resize(p.points.size());
  for (size_t i = 0; i < p.points.size(); ++i) {
    const double s = pl.signed_distance(p.points[i]);
    below |= s < -eps;
    above |= s > eps;
    dist[i] = std::abs(s) <= eps ? 0 : s;
  }
  return below && above ? 0 : (above ? 1 : -1);
}

// A monotone stand-in for the angle of (x, y) in [0, 4) (no atan2: only the order matters).
double pseudo_angle(double x, double y) {
  const double r = y / (std::abs(x) + std::abs(y));
  return x < 0 ? 2 - r : (y < 0 ? 4 + r : r);
}

// The new face on the cutting plane from the points found on it, appended to `out`: sorted
// counter-clockwise seen from +n (the kept side's outside), near-duplicates dropped.
void add_cap(std::vector<Vec3>& pts, const Vec3& n, double eps, ConvexPolytope& out) {
  if (pts.size() < 3) return;
  Vec3 c{0, 0, 0};
  for (const Vec3& q : pts) c += q;
  c = c / static_cast<double>(pts.size());
  const Vec3 axis = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(n, axis));
  const Vec3 v = cross(n, u);
  thread_local std::vector<std::pair<double, Vec3>> by_angle;
  by_angle.clear();
  for (const Vec3& q : pts) {
    const double x = dot(q - c, u), y = dot(q - c, v);
    by_angle.push_back({x == 0 && y == 0 ? 0.0 : pseudo_angle(x, y), q});
  }
  std::sort(by_angle.begin(), by_angle.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const size_t begin = out.points.size();
  for (const auto& [angle, q] : by_angle)
    if (out.points.size() == begin || norm(q - out.points.back()) > eps) out.points.push_back(q);
  while (out.points.size() > begin + 1 && norm(out.points[begin] - out.points.back()) <= eps)
    out.points.pop_back();
  out.close_face();
}

}  // namespace

namespace {

// clip_polytope for a plane that cuts `p` (polytope_side 0), from its points' distances `dist`
// (a face's edges read them at both ends).
void clip_cut(const ConvexPolytope& p, const Plane& keep_below, double eps, const std::vector<double>& dist,
              ConvexPolytope& out) {
  out.clear();
  thread_local std::vector<Vec3> on_plane;
  on_plane.clear();
  bool has_cap = false;  // a face of `p` lies on the plane: it is the cut's face already
  for (size_t f = 0; f < p.face_count(); ++f) {
    const uint32_t b = p.face_begin(f), e = p.ends[f];
    bool all_on = true;
    for (uint32_t i = b; i < e; ++i) {
      const uint32_t j = i + 1 < e ? i + 1 : b;
      const Vec3& x0 = p.points[i];
      const Vec3& x1 = p.points[j];
      const double s0 = dist[i], s1 = dist[j];
      all_on &= s0 == 0;
      if (s0 <= 0) out.points.push_back(x0);
      if (s0 == 0) on_plane.push_back(x0);
      if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
        // From the kept end, so that the two faces sharing the edge find the same point.
        const Vec3 x = s0 < 0 ? x0 + (x1 - x0) * (s0 / (s0 - s1)) : x1 + (x0 - x1) * (s1 / (s1 - s0));
        out.points.push_back(x);
        on_plane.push_back(x);
      }
    }
    has_cap |= all_on;
    out.close_face();
  }
  if (!has_cap) add_cap(on_plane, keep_below.n, eps, out);
}

}  // namespace

void clip_polytope(const ConvexPolytope& p, const Plane& keep_below, double eps, ConvexPolytope& out) {
  thread_local std::vector<double> dist;
  const int side = polytope_side(p, keep_below, eps, dist);
  if (side < 0) {
    out = p;
    return;
  }
  out.clear();
  if (side > 0) return;
  clip_cut(p, keep_below, eps, dist, out);
}

ColumnVolume::ColumnVolume(const TriangleSoup& soup) {
  BBox all;
  for (const Vec3& v : soup.vertices) all.add(v);
  scale_ = all.valid() ? all.diagonal() : 1.0;
  const Vec3 ref = all.valid() ? all.center() : Vec3{0, 0, 0};
  double six = 0;
  for (const auto& t : soup.triangles) {
    const Vec3 a = soup.vertices[t[0]] - ref, b = soup.vertices[t[1]] - ref, c = soup.vertices[t[2]] - ref;
    six += dot(a, cross(b, c));
  }
  const double orientation = six < 0 ? -1.0 : 1.0;
  for (const auto& t : soup.triangles) {
    Vec3 a = soup.vertices[t[0]], b = soup.vertices[t[1]], c = soup.vertices[t[2]];
    const Vec3 nrm = cross(b - a, c - a);
    if (!(std::abs(nrm.z) > 1e-12 * norm(nrm))) continue;  // vertical (or degenerate): no column
    if (nrm.z < 0) std::swap(b, c);                        // counter-clockwise in plan
    Column col{a, b, c, nrm.z * orientation > 0 ? 1.0 : -1.0, {}};
    col.box.add(a);
    col.box.add(b);
    col.box.add(c);
    columns_.push_back(col);
  }
  if (columns_.empty()) return;
  BBox plan;
  for (const Column& col : columns_) {
    plan.add(col.box.lo);
    plan.add(col.box.hi);
  }
  const double k = std::ceil(std::sqrt(static_cast<double>(columns_.size())));
  const Vec3 ext = plan.hi - plan.lo;
  step_ = std::max({ext.x, ext.y, 1e-9 * (1 + scale_)}) / k;
  x0_ = plan.lo.x;
  y0_ = plan.lo.y;
  nx_ = std::max(1, static_cast<int>(std::ceil(ext.x / step_)) + 1);
  ny_ = std::max(1, static_cast<int>(std::ceil(ext.y / step_)) + 1);
  grid_.assign(static_cast<size_t>(nx_) * ny_, {});
  for (uint32_t i = 0; i < columns_.size(); ++i) {
    const BBox& b = columns_[i].box;
    const int i0 = std::clamp(static_cast<int>((b.lo.x - x0_) / step_), 0, nx_ - 1);
    const int i1 = std::clamp(static_cast<int>((b.hi.x - x0_) / step_), 0, nx_ - 1);
    const int j0 = std::clamp(static_cast<int>((b.lo.y - y0_) / step_), 0, ny_ - 1);
    const int j1 = std::clamp(static_cast<int>((b.hi.y - y0_) / step_), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int ii = i0; ii <= i1; ++ii) grid_[static_cast<size_t>(j) * nx_ + ii].push_back(i);
  }
}

std::vector<uint32_t> ColumnVolume::candidates(const BBox& box, size_t limit) const {
  std::vector<uint32_t> ids;
  if (columns_.empty()) return ids;
  // Clamped before the cast: a box far outside the grid must not overflow an int.
  auto cell_of = [this](double v, double v0, int n) {
    return static_cast<int>(std::clamp((v - v0) / step_, 0.0, static_cast<double>(n - 1)));
  };
  const int i0 = cell_of(box.lo.x, x0_, nx_), i1 = cell_of(box.hi.x, x0_, nx_);
  const int j0 = cell_of(box.lo.y, y0_, ny_), j1 = cell_of(box.hi.y, y0_, ny_);
  // A column listed in several grid cells is taken once: marked with this query's stamp (per
  // thread, so that the two children of a split are measured at once).
  thread_local StampedTable<bool> seen;
  seen.next_round(columns_.size());
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      for (uint32_t t : grid_[static_cast<size_t>(j) * nx_ + i]) {
        if (seen.find(t)) continue;
        seen.set(t, true);
        const BBox& b = columns_[t].box;
        // A column matters when its triangle overlaps the cell in plan and rises above its floor.
        if (b.lo.x <= box.hi.x && box.lo.x <= b.hi.x && b.lo.y <= box.hi.y && box.lo.y <= b.hi.y &&
            b.hi.z > box.lo.z) {
          ids.push_back(t);
          if (ids.size() > limit) return ids;  // more than the caller will measure
        }
      }
    }
  return ids;
}

double ColumnVolume::under(const ConvexPolytope& cell, const Column& t, double eps) const {
  // Below the triangle's plane (normal up), then inside its projection (edges counter-clockwise:
  // the outward side of edge p→q is to its right).
  Plane planes[4];
  const Vec3 up = normalized(cross(t.b - t.a, t.c - t.a));
  planes[0] = {up, -dot(up, t.a)};
  const Vec3* corner[3] = {&t.a, &t.b, &t.c};
  for (int e = 0; e < 3; ++e) {
    const Vec3& p = *corner[e];
    const Vec3& q = *corner[(e + 1) % 3];
    const Vec3 n = normalized(Vec3{q.y - p.y, p.x - q.x, 0});
    planes[e + 1] = {n, -dot(n, p)};
  }
  // Two scratch polytopes per thread, clipped into one from the other.
  thread_local ConvexPolytope scratch[2];
  const ConvexPolytope* at = &cell;
  int next = 0;
  thread_local std::vector<double> dist;
  for (const Plane& pl : planes) {
    const int side = polytope_side(*at, pl, eps, dist);
    if (side > 0) return 0;
    if (side < 0) continue;
    clip_cut(*at, pl, eps, dist, scratch[next]);
    at = &scratch[next];
    next ^= 1;
    if (at->empty()) return 0;
  }
  return polytope_volume(*at);
}

double ColumnVolume::inside(const ConvexPolytope& cell, const BBox& box, size_t max_columns) const {
  const double eps = 1e-9 * (1 + scale_);
  std::vector<uint32_t> ids = candidates(box, max_columns > 0 ? max_columns : SIZE_MAX);
  if (max_columns > 0 && ids.size() > max_columns) return -1;
  std::sort(ids.begin(), ids.end());  // one order of summation: the same sum on every run
  double v = 0;
  for (uint32_t t : ids) v += columns_[t].sign * under(cell, columns_[t], eps);
  return std::clamp(v, 0.0, std::max(0.0, polytope_volume(cell)));
}

}  // namespace mc
