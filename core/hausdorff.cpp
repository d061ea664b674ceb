#include "core/hausdorff.hpp"

#include "core/geometry.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <initializer_list>
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
// Each kept piece goes to `emit(origin, e1, e2, n, weight)`, its points being origin + i·e1 + j·e2
// (i + j <= n), each standing for `weight` of area; with `emit` null the points are only counted
// into `count` (the same tests, so the same outcome).
// A piece for which `skip(piece)` is true is dropped with all its points (counting never skips).
using Piece = std::array<K::Point_3, 3>;
struct NoSkip {
  bool operator()(const Piece&) const { return false; }
};
template <class Emit, class Skip = NoSkip>
bool lattice(const K::Triangle_3& t, double step, size_t budget, const Emit* emit, size_t& count,
             const Skip& skip = Skip()) {
  // The pieces still to cut, reused between calls (this runs once per triangle and step tried).
  static thread_local std::vector<Piece> stack;
  stack.assign(1, {t[0], t[1], t[2]});
  while (!stack.empty()) {
    const Piece tri = stack.back();
    stack.pop_back();
    if (skip(tri)) continue;
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
    if (emit) (*emit)(tri[0], e1, e2, n, w);
    if (count > budget) return false;
  }
  return true;
}

// A lattice point, computed as every caller computes it (the maxima are compared bit for bit).
K::Point_3 lattice_point(const K::Point_3& o, const K::Vector_3& e1, const K::Vector_3& e2, int i, int j) {
  return o + i * e1 + j * e2;
}

// The counting instance's (never called) type.
using Emit = void (*)(const K::Point_3&, const K::Vector_3&, const K::Vector_3&, int, double);

bool count_lattice(const K::Triangle_3& t, double step, size_t budget, size_t& count) {
  return lattice<Emit>(t, step, budget, nullptr, count);
}

void sample_triangle(const K::Triangle_3& t, double step, size_t budget, Samples& s, size_t& count) {
  const auto emit = [&s](const K::Point_3& o, const K::Vector_3& e1, const K::Vector_3& e2, int n, double w) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        s.points.push_back(lattice_point(o, e1, e2, i, j));
        s.weights.push_back(w);
      }
  };
  lattice(t, step, budget, &emit, count);
}

// Every triangle gets at least its 3 corners, so the budget must allow that.
size_t budget_for(const Triangles& tris, size_t budget) { return std::max(budget, 4 * tris.size()); }

// A lower bound of lattice()'s count at a step, from each triangle's longest edge and area alone.
// A triangle lattice() never cuts (fat) has exactly (n + 1)(n + 2) / 2 points. A sliver's kept
// pieces each have n = ceil(len / step) >= len / step subdivisions, so (n + 1)(n + 2) / 2 >= 3n
// points and more than 2 · area / (√3 · step²) (a triangle's area is at most √3/4 of its longest
// edge squared); halving a longest edge leaves each half at least half of it and the area is
// shared, so the sliver holds at least 3 · len / step and 1.15 · area / step² points (both shrunk by
// 10⁻⁶ for the halves' rounding).
class CountBound {
 public:
  explicit CountBound(const Triangles& tris) {
    for (const auto& t : tris) {
      double len2 = -1;
      for (int i = 0; i < 3; ++i)
        len2 = std::max(len2, CGAL::to_double(CGAL::squared_distance(t[i], t[(i + 1) % 3])));
      const double len = std::sqrt(len2);  // as lattice() computes them
      const double area = std::sqrt(CGAL::to_double(t.squared_area()));
      if (!std::isfinite(len) || !std::isfinite(area)) continue;
      if (!(2 * area / len < len / 4)) fat_.push_back(len);
      else sliver_.push_back({len * (1 - 1e-6), area * (1 - 1e-6)});
    }
  }
  // True when the lattice at `step` certainly holds more than `budget` points.
  bool exceeds(double step, size_t budget) const {
    const double b = static_cast<double>(budget), most = std::sqrt(b) + 1;
    double sum = 0;
    for (double len : fat_) {
      if (len / step > most) return true;  // lattice() fails on it
      const double n = std::max(1.0, std::ceil(len / step));
      sum += (n + 1) * (n + 2) / 2;
    }
    for (const auto& [len, area] : sliver_)
      sum += std::max(3 * std::floor(len / step), 1.1547 * area / (step * step));
    return sum > b;
  }

 private:
  std::vector<double> fat_;                        // longest edges of the triangles never cut
  std::vector<std::pair<double, double>> sliver_;  // longest edge and area of the others
};

// The step of sample(): `step`, grown until the lattice of all triangles fits the budget. Found by
// counting (cheap; a step whose lower bound exceeds the budget is not even counted); `*total` = the
// number of points at that step.
double step_within(const Triangles& tris, double step, size_t budget, size_t* total) {
  const CountBound bound(tris);
  for (;;) {
    while (bound.exceeds(step, budget)) step *= 1.5;
    *total = 0;
    bool ok = true;
    for (const auto& t : tris)
      if (!(ok = count_lattice(t, step, budget, *total))) break;
    if (ok) return step;
    step *= 1.5;
  }
}

// Samples of all triangles; the step grows when `budget` would be exceeded. `*used` = step.
Samples sample(const Triangles& tris, double step, size_t budget, double* used) {
  budget = budget_for(tris, budget);
  size_t total = 0;
  step = step_within(tris, step, budget, &total);
  Samples s;
  s.points.reserve(total);
  s.weights.reserve(total);
  size_t count = 0;
  for (const auto& t : tris) sample_triangle(t, step, budget, s, count);
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

  // The distance from p to triangle t, exact in doubles.
  double distance_to(const Vec3& p, uint32_t t) const { return std::sqrt(squared(p, t)); }
  double slack() const { return slack_; }

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

Vec3 vec(const K::Point_3& p) { return {p.x(), p.y(), p.z()}; }

std::vector<double> distances(const ClosestPoints& to, const std::vector<K::Point_3>& pts) {
  std::vector<double> d(pts.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, d.size(), 1024),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      uint32_t hint = UINT32_MAX;
                      for (size_t i = r.begin(); i != r.end(); ++i) d[i] = to.distance(vec(pts[i]), hint);
                    }));
  return d;
}

// The maximum of sample()'s lattice with few closest-point queries. The distance to one triangle
// t is convex, so over a piece of a triangle of `from` (a lattice row, a piece lattice() cuts, the
// triangle itself) it is at most its largest value at the piece's corners, and the distance to the
// soup is at most that for any t. With t among the triangles nearest to the triangle's corners and
// the last one found nearest, a piece whose bound stays below the corners' maximum cannot hold the
// lattice's maximum: its points need no query (the coincident surfaces of a cell and its input).
// The corner holding the maximum is never skipped (every bound of it is at least its distance), so
// the maximum is the full lattice's, bit for bit; the slack covers the rounding between a corner
// and its lattice point.
class LatticeMaximum {
 public:
  // `bar`: the largest distance found so far less the slack, shared by the triangles' searches
  // (raised as they find more; a point under it cannot be the maximum, whatever the order).
  LatticeMaximum(const ClosestPoints& nearest, const uint32_t* candidates, std::atomic<double>& bar)
      : nearest_(nearest), cand_(candidates), bar_(bar), slack_(2 * nearest.slack()), hint_(candidates[0]) {}

  // The largest distance of a lattice point of `t` that can reach the bar (0 if none can).
  double of(const K::Triangle_3& t, double step, size_t budget) {
    const auto visit = [this](const K::Point_3& o, const K::Vector_3& e1, const K::Vector_3& e2, int n,
                              double) { piece(o, e1, e2, n); };
    const auto skip = [this](const Piece& p) { return settled({vec(p[0]), vec(p[1]), vec(p[2])}); };
    size_t count = 0;
    lattice(t, step, budget, &visit, count, skip);
    return most_;
  }

 private:
  // True when one known triangle is nearer than the bar at every point given (hence between them).
  bool settled(std::initializer_list<Vec3> points) {
    const double below = bar_.load(std::memory_order_relaxed);
    for (int c = -1; c < 3; ++c) {
      const uint32_t t = c < 0 ? hint_ : cand_[c];
      if (c >= 0 && t == hint_) continue;
      bool all = true;
      for (const Vec3& p : points) all = all && nearest_.distance_to(p, t) < below;
      if (all) {
        hint_ = t;
        return true;
      }
    }
    return false;
  }
  void piece(const K::Point_3& o, const K::Vector_3& e1, const K::Vector_3& e2, int n) {
    for (int a = 0; a <= n; ++a) {
      if (settled({vec(lattice_point(o, e1, e2, a, 0)), vec(lattice_point(o, e1, e2, a, n - a))})) continue;
      for (int b = 0; a + b <= n; ++b) {
        const Vec3 p = vec(lattice_point(o, e1, e2, a, b));
        if (settled({p})) continue;
        const double d = nearest_.distance(p, hint_);
        if (!(d > most_)) continue;
        most_ = d;
        const double raised = d - slack_;
        for (double now = bar_.load(std::memory_order_relaxed); raised > now;)
          if (bar_.compare_exchange_weak(now, raised, std::memory_order_relaxed)) break;
      }
    }
  }
  const ClosestPoints& nearest_;
  const uint32_t* cand_;  // the nearest triangles of the triangle's three corners
  std::atomic<double>& bar_;
  double slack_;
  uint32_t hint_;  // the last triangle that settled a piece or was found nearest
  double most_ = 0;
};

double lattice_maximum(const Triangles& from, const ClosestPoints& nearest, double step) {
  const size_t budget = budget_for(from, kMeanSamples);
  size_t total = 0;
  step = step_within(from, step, budget, &total);
  // Each distinct corner is queried once (a vertex is a corner of about six triangles).
  std::vector<uint32_t> order(3 * from.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto corner = [&](uint32_t i) -> const K::Point_3& { return from[i / 3][i % 3]; };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return corner(a) < corner(b); });
  std::vector<uint32_t> first;  // the positions in `order` where a distinct corner starts
  for (uint32_t k = 0; k < order.size(); ++k)
    if (k == 0 || corner(order[k - 1]) != corner(order[k])) first.push_back(k);
  first.push_back(static_cast<uint32_t>(order.size()));
  std::vector<double> d(first.size() - 1);
  std::vector<uint32_t> near(3 * from.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, d.size(), 128),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      uint32_t hint = UINT32_MAX;
                      for (size_t u = r.begin(); u != r.end(); ++u) {
                        d[u] = nearest.distance(vec(corner(order[first[u]])), hint);
                        for (uint32_t k = first[u]; k < first[u + 1]; ++k) near[order[k]] = hint;
                      }
                    }));
  std::atomic<double> bar{*std::max_element(d.begin(), d.end()) - 2 * nearest.slack()};
  std::vector<double> most(from.size(), 0);  // per triangle: the serial max below is thread-free
  tbb::parallel_for(tbb::blocked_range<size_t>(0, from.size(), 4),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i)
                        most[i] = LatticeMaximum(nearest, &near[3 * i], bar).of(from[i], step, budget);
                    }));
  return *std::max_element(most.begin(), most.end());
}

OneSided one_sided(const Triangles& from, const Triangles& to, double step, bool means) {
  if (from.empty()) return {};
  if (to.empty()) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  const ClosestPoints nearest(to);
  if (!means) return {lattice_maximum(from, nearest, step), 0};
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

HausdorffResult hausdorff(const TriangleSoup& a, const TriangleSoup& b, double sampling_step, bool means) {
  BBox box;
  for (const Vec3& v : a.vertices) box.add(v);
  for (const Vec3& v : b.vertices) box.add(v);
  const Vec3 origin = box.valid() ? box.center() : Vec3{};
  if (!(sampling_step > 0)) sampling_step = std::max(box.diagonal(), 1e-9) * 1e-3;
  const Triangles ta = triangles_of(a, origin), tb = triangles_of(b, origin);
  const OneSided ab = one_sided(ta, tb, sampling_step, means);
  const OneSided ba = one_sided(tb, ta, sampling_step, means);
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
