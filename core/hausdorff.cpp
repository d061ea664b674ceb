#include "core/hausdorff.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/aabb_triangles.hpp"
#include "core/plane.hpp"

namespace mc {

namespace {

using aabb::K;
using aabb::Primitive;
using aabb::Tree;
using aabb::Triangles;

// Samples per side at most (the step is coarsened beyond). Every triangle's corners and edges are
// sampled at any step, and that is where the maximum of two nearly coincident surfaces lies, so a
// budget well below the step's full lattice keeps the maxima (measured: docs/benchmarks.md, "Speed").
constexpr size_t kMeanSamples = 8000;

K::Point_3 to_point(const Vec3& v, const Vec3& origin) {
  const Vec3 p = v - origin;
  return {p.x, p.y, p.z};
}

// Non-degenerate triangles of the soup, translated by -origin (keeps doubles well-conditioned
// for georeferenced coordinates).
Triangles triangles_of(const TriangleSoup& s, const Vec3& origin) {
  Triangles out;
  out.reserve(s.triangles.size());
  for (const auto& t : s.triangles) {
    K::Triangle_3 tri(to_point(s.vertices[t[0]], origin), to_point(s.vertices[t[1]], origin),
                      to_point(s.vertices[t[2]], origin));
    bool finite = true;
    for (int k = 0; k < 3; ++k) finite = finite && is_finite(s.vertices[t[k]]);
    if (finite && !tri.is_degenerate()) out.push_back(tri);
  }
  return out;
}

struct Samples {
  std::vector<K::Point_3> points;
  std::vector<double> weights;  // area represented by each point
};

// Barycentric lattice with n subdivisions per edge (n = ceil(longest edge / step)): every
// point lies in a lattice cell with edges <= step. A lattice on a sliver would cost
// (length/step)^2 points for almost no area, so slivers are first cut by longest-edge
// bisection until the pieces are fat or short; their cost is then linear in their length.
bool sample_triangle(const K::Triangle_3& t, double step, size_t budget, Samples& s) {
  std::vector<std::array<K::Point_3, 3>> stack{{t[0], t[1], t[2]}};
  while (!stack.empty()) {
    const auto tri = stack.back();
    stack.pop_back();
    int longest = 0;
    double len2 = -1;
    for (int i = 0; i < 3; ++i) {
      const double l = CGAL::to_double(CGAL::squared_distance(tri[i], tri[(i + 1) % 3]));
      if (l > len2) {
        len2 = l;
        longest = i;
      }
    }
    const double len = std::sqrt(len2);
    const double area = std::sqrt(CGAL::to_double(K::Triangle_3(tri[0], tri[1], tri[2]).squared_area()));
    const double min_altitude = 2 * area / len;
    if (s.points.size() + stack.size() > budget) return false;
    if (len > step && min_altitude < len / 4) {  // a sliver: bisect its longest edge
      const K::Point_3& a = tri[longest];
      const K::Point_3& b = tri[(longest + 1) % 3];
      const K::Point_3& c = tri[(longest + 2) % 3];
      const K::Point_3 m = CGAL::midpoint(a, b);
      stack.push_back({a, m, c});
      stack.push_back({m, b, c});
      continue;
    }
    if (!std::isfinite(len) || !std::isfinite(area)) continue;
    if (len / step > std::sqrt(static_cast<double>(budget)) + 1) return false;  // coarsen the step first
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    const K::Vector_3 e1 = (tri[1] - tri[0]) / n, e2 = (tri[2] - tri[0]) / n;
    const double w = area / ((n + 1.0) * (n + 2.0) / 2);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        s.points.push_back(tri[0] + i * e1 + j * e2);
        s.weights.push_back(w);
      }
    if (s.points.size() > budget) return false;
  }
  return true;
}

// Samples of all triangles; the step grows when `budget` would be exceeded. `*used` = step.
Samples sample(const Triangles& tris, double step, size_t budget, double* used) {
  // Every triangle gets at least its 3 corners, so the budget must allow that.
  budget = std::max(budget, 4 * tris.size());
  for (;;) {
    Samples s;
    bool ok = true;
    for (const auto& t : tris)
      if (!(ok = sample_triangle(t, step, budget, s))) break;
    if (ok) {
      *used = step;
      return s;
    }
    step *= 1.5;
  }
}

struct OneSided {
  double max = 0, mean = 0;
};

std::vector<double> distances(const Tree& tree, const std::vector<K::Point_3>& pts) {
  std::vector<double> d(pts.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, d.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
    // Consecutive samples are neighbours on one triangle: the previous closest point is a
    // tighter hint than the tree's default.
    K::Point_3 hint = tree.closest_point(pts[r.begin()]);
    for (size_t i = r.begin(); i != r.end(); ++i) {
      hint = tree.closest_point(pts[i], hint);
      d[i] = std::sqrt(CGAL::to_double(CGAL::squared_distance(pts[i], hint)));
    }
  });
  return d;
}

OneSided one_sided(const Triangles& from, const Triangles& to, double step) {
  if (from.empty()) return {};
  if (to.empty()) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Tree tree(to.begin(), to.end());
  tree.accelerate_distance_queries();
  // Mean (and a first maximum) from a sampling of bounded size.
  double mean_step = step;
  const Samples s = sample(from, step, kMeanSamples, &mean_step);
  const std::vector<double> d = distances(tree, s.points);
  OneSided out;
  double wsum = 0;
  for (size_t i = 0; i < d.size(); ++i) {  // serial sums: the result does not depend on threads
    out.max = std::max(out.max, d[i]);
    out.mean += s.weights[i] * d[i];
    wsum += s.weights[i];
  }
  out.mean = wsum > 0 ? out.mean / wsum : 0;
  // The maximum is the sampled maximum at the (possibly coarsened) step: exact up to that step.
  // A branch-and-bound refinement was tried and removed: it degenerated on coincident surfaces.
  return out;
}

}  // namespace

HausdorffResult hausdorff(const TriangleSoup& a, const TriangleSoup& b, double sampling_step) {
  BBox box;
  for (const Vec3& v : a.vertices) box.add(v);
  for (const Vec3& v : b.vertices) box.add(v);
  const Vec3 origin = box.valid() ? box.center() : Vec3{};
  if (!(sampling_step > 0)) sampling_step = std::max(box.diagonal(), 1e-9) * 1e-3;
  const Triangles ta = triangles_of(a, origin), tb = triangles_of(b, origin);
  const OneSided ab = one_sided(ta, tb, sampling_step);
  const OneSided ba = one_sided(tb, ta, sampling_step);
  HausdorffResult r;
  r.a_to_b = ab.max;
  r.b_to_a = ba.max;
  r.symmetric = std::max(ab.max, ba.max);
  r.mean_a_to_b = ab.mean;
  r.mean_b_to_a = ba.mean;
  r.mean_symmetric = (ab.mean + ba.mean) / 2;
  return r;
}

}  // namespace mc
