#include "core/hausdorff.hpp"

#include "core/geometry.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/aabb_triangles.hpp"
#include "core/embree_device.hpp"
#include "core/plane.hpp"
#include "core/thread_tag.hpp"

namespace mc {

namespace {

using aabb::K;
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
// With `s` null only counts the points into `count` (the same tests, so the same outcome).
bool sample_triangle(const K::Triangle_3& t, double step, size_t budget, Samples* s, size_t& count) {
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
    if (count + stack.size() > budget) return false;
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
    count += static_cast<size_t>(n + 1) * static_cast<size_t>(n + 2) / 2;
    if (s)
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
          s->points.push_back(tri[0] + i * e1 + j * e2);
          s->weights.push_back(w);
        }
    if (count > budget) return false;
  }
  return true;
}

// Samples of all triangles; the step grows when `budget` would be exceeded. `*used` = step.
Samples sample(const Triangles& tris, double step, size_t budget, double* used) {
  // Every triangle gets at least its 3 corners, so the budget must allow that.
  budget = std::max(budget, 4 * tris.size());
  // The step is found by counting (cheap), and the points made once.
  size_t total = 0;
  for (;;) {
    total = 0;
    bool ok = true;
    for (const auto& t : tris)
      if (!(ok = sample_triangle(t, step, budget, nullptr, total))) break;
    if (ok) break;
    step *= 1.5;
  }
  Samples s;
  s.points.reserve(total);
  s.weights.reserve(total);
  size_t count = 0;
  for (const auto& t : tris) sample_triangle(t, step, budget, &s, count);
  *used = step;
  return s;
}

struct OneSided {
  double max = 0, mean = 0;
};

// Closest-point queries on a triangle set: an Embree BVH (float) finds the candidates, whose
// distances are exact in doubles. Embree's boxes hold the float copies of the vertices, so the
// query radius it culls with is the best distance so far plus `margin_` (a few float ulps of
// the coordinates): no triangle within the best distance is ever culled.
class ClosestPoints {
 public:
  explicit ClosestPoints(const Triangles& tris) {
    double extent = 0;
    for (const auto& t : tris) {
      std::array<Vec3, 3> v;
      for (int k = 0; k < 3; ++k) {
        v[k] = {t[k].x(), t[k].y(), t[k].z()};
        extent = std::max({extent, std::abs(v[k].x), std::abs(v[k].y), std::abs(v[k].z)});
      }
      tris_.push_back(v);
      // The plane, where the normal is well defined (not a sliver): its distance bounds the
      // triangle's from below (see `visit`).
      const Vec3 c = cross(v[1] - v[0], v[2] - v[0]);
      const double longest2 = std::max(
          {dot(v[1] - v[0], v[1] - v[0]), dot(v[2] - v[1], v[2] - v[1]), dot(v[0] - v[2], v[0] - v[2])});
      const double len = norm(c);
      if (len > 1e-6 * longest2) {  // |normal error| <= ulp · longest² / |c| <= 1e-10
        const Vec3 n = c / len;
        planes_.push_back({n.x, n.y, n.z, -dot(n, v[0])});
      } else {
        planes_.push_back({0, 0, 0, 0});  // never rejects
      }
    }
    margin_ = static_cast<float>(1e-5 * std::max(extent, 1e-9));
    slack_ = 1e-8 * std::max(extent, 1e-9);
    scene_ = rtcNewScene(shared_embree_device());
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(shared_embree_device(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), 3 * tris_.size()));
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris_.size()));
    for (size_t i = 0; i < tris_.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        vb[9 * i + 3 * k] = static_cast<float>(tris_[i][k].x);
        vb[9 * i + 3 * k + 1] = static_cast<float>(tris_[i][k].y);
        vb[9 * i + 3 * k + 2] = static_cast<float>(tris_[i][k].z);
        ib[3 * i + k] = static_cast<unsigned>(3 * i + k);
      }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(shared_embree_device()) != RTC_ERROR_NONE) {
      rtcReleaseScene(scene_);
      throw std::runtime_error("Embree: closest-point scene build failed");
    }
  }
  ~ClosestPoints() { rtcReleaseScene(scene_); }
  ClosestPoints(const ClosestPoints&) = delete;
  ClosestPoints& operator=(const ClosestPoints&) = delete;

  // The distance from p to the nearest triangle; `hint` (a triangle index, updated) is tried
  // first: consecutive samples of one triangle mostly share their nearest triangle.
  double distance(const Vec3& p, uint32_t& hint) const {
    Query q{this, p, std::numeric_limits<double>::infinity(), hint};
    if (hint < tris_.size()) q.best2 = squared(p, hint);
    RTCPointQuery pq;
    pq.x = static_cast<float>(p.x);
    pq.y = static_cast<float>(p.y);
    pq.z = static_cast<float>(p.z);
    pq.time = 0;
    pq.radius = std::isfinite(q.best2) ? static_cast<float>(std::sqrt(q.best2)) + margin_
                                       : std::numeric_limits<float>::infinity();
    RTCPointQueryContext ctx;
    rtcInitPointQueryContext(&ctx);
    rtcPointQuery(scene_, &pq, &ctx, &ClosestPoints::visit, &q);
    hint = q.best;
    return std::sqrt(q.best2);
  }

 private:
  struct Query {
    const ClosestPoints* self;
    Vec3 p;
    double best2;
    uint32_t best;
  };
  double squared(const Vec3& p, uint32_t t) const {
    const auto& v = tris_[t];
    const Vec3 d = p - closest_on_triangle(p, v[0], v[1], v[2]);
    return dot(d, d);
  }
  static bool visit(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<Query*>(args->userPtr);
    if (args->primID == q->best) return false;
    // A triangle whose plane is farther than the best distance so far cannot be closer. The
    // slack (10⁻⁸ of the coordinates, far above the plane's rounding) keeps every triangle whose
    // computed distance could tie or win, so the result is the one without this test.
    const auto& pl = q->self->planes_[args->primID];
    if (std::abs(pl[0] * q->p.x + pl[1] * q->p.y + pl[2] * q->p.z + pl[3]) >
        std::sqrt(q->best2) + q->self->slack_)
      return false;
    const double d2 = q->self->squared(q->p, args->primID);
    if (!(d2 < q->best2)) return false;
    q->best2 = d2;
    q->best = args->primID;
    args->query->radius = static_cast<float>(std::sqrt(d2)) + q->self->margin_;
    return true;
  }
  std::vector<std::array<Vec3, 3>> tris_;
  std::vector<std::array<double, 4>> planes_;  // unit normal and offset; zero for slivers
  float margin_ = 0;
  double slack_ = 0;
  RTCScene scene_ = nullptr;
};

std::vector<double> distances(const ClosestPoints& to, const std::vector<K::Point_3>& pts) {
  std::vector<double> d(pts.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, d.size(), 1024),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      uint32_t hint = UINT32_MAX;
                      for (size_t i = r.begin(); i != r.end(); ++i)
                        d[i] = to.distance({pts[i].x(), pts[i].y(), pts[i].z()}, hint);
                    }));
  return d;
}

OneSided one_sided(const Triangles& from, const Triangles& to, double step) {
  if (from.empty()) return {};
  if (to.empty()) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  const ClosestPoints nearest(to);
  // Mean (and a first maximum) from a sampling of bounded size.
  double mean_step = step;
  const Samples s = sample(from, step, kMeanSamples, &mean_step);
  const std::vector<double> d = distances(nearest, s.points);
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
