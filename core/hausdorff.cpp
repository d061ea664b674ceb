#include "core/hausdorff.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/plane.hpp"

namespace mc {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

constexpr double kMaxSamples = 4e6;

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
    if (!tri.is_degenerate()) out.push_back(tri);
  }
  return out;
}

int subdivisions(const K::Triangle_3& t, double step) {
  double longest = 0;
  for (int i = 0; i < 3; ++i) longest = std::max(longest, std::sqrt(CGAL::to_double(CGAL::squared_distance(t[i], t[(i + 1) % 3]))));
  return std::max(1, static_cast<int>(std::ceil(longest / step)));
}

struct Samples {
  std::vector<K::Point_3> points;
  std::vector<double> weights;  // triangle area / samples of that triangle
};

// Barycentric lattice with n subdivisions per edge: every point of the triangle lies within
// one lattice cell, whose edges are at most `step` long.
Samples sample(const Triangles& tris, double step) {
  double total = 0;
  for (const auto& t : tris) {
    const double n = subdivisions(t, step);
    total += (n + 1) * (n + 2) / 2;
  }
  if (total > kMaxSamples) step *= std::sqrt(total / kMaxSamples) * 1.01;
  Samples s;
  for (const auto& t : tris) {
    const int n = subdivisions(t, step);
    const K::Vector_3 e1 = (t[1] - t[0]) / n, e2 = (t[2] - t[0]) / n;
    const double w = std::sqrt(CGAL::to_double(t.squared_area())) / ((n + 1.0) * (n + 2.0) / 2);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        s.points.push_back(t[0] + i * e1 + j * e2);
        s.weights.push_back(w);
      }
  }
  return s;
}

struct OneSided {
  double max = 0, mean = 0;
};

OneSided one_sided(const Triangles& from, const Triangles& to, double step) {
  if (from.empty()) return {};
  if (to.empty()) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Tree tree(to.begin(), to.end());
  tree.accelerate_distance_queries();
  const Samples s = sample(from, step);
  std::vector<double> d(s.points.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, d.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) d[i] = std::sqrt(CGAL::to_double(tree.squared_distance(s.points[i])));
  });
  OneSided out;
  double wsum = 0;
  for (size_t i = 0; i < d.size(); ++i) {  // serial sums: the result does not depend on threads
    out.max = std::max(out.max, d[i]);
    out.mean += s.weights[i] * d[i];
    wsum += s.weights[i];
  }
  out.mean = wsum > 0 ? out.mean / wsum : 0;
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
  return r;
}

}  // namespace mc
