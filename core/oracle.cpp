#include "core/hashing.hpp"
#include "core/oracle.hpp"
#include "core/embree_device.hpp"
#include "core/fast_sincos.hpp"
#include "core/union_find.hpp"
#include "core/thread_tag.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <map>
#include <unordered_map>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace mc {

namespace {

using Hits = std::vector<std::pair<float, unsigned>>;  // (t, primitive id)

// Context extended with the hit lists of the rays traced together, indexed by the rays' ids (the
// usual Embree idiom: the filter casts back).
struct CollectContext {
  RTCIntersectContext base;
  Hits* hits[4];
};

// Records every hit and rejects it, so traversal continues to the end of the ray.
void collect_filter(const RTCFilterFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<CollectContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    ctx->hits[RTCRayN_id(args->ray, args->N, i)]->emplace_back(RTCRayN_tfar(args->ray, args->N, i),
                                                               RTCHitN_primID(args->hit, args->N, i));
    args->valid[i] = 0;
  }
}

// A ray from o (in the scene's centred frame) along dir, over its whole length.
RTCRay make_ray(const Vec3& o, const Vec3& dir) {
  RTCRay ray;
  ray.org_x = static_cast<float>(o.x);
  ray.org_y = static_cast<float>(o.y);
  ray.org_z = static_cast<float>(o.z);
  ray.dir_x = static_cast<float>(dir.x);
  ray.dir_y = static_cast<float>(dir.y);
  ray.dir_z = static_cast<float>(dir.z);
  ray.tnear = 0.0f;
  ray.tfar = std::numeric_limits<float>::infinity();
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  ray.time = 0;
  ray.id = 0;
  return ray;
}

}  // namespace

struct InsideOracle::Impl {
  RTCScene scene = nullptr;
  Vec3 origin;         // soup bbox centre: Embree works in float, so coordinates are centred
  double dedup_t = 0;  // hits closer than this along a ray are one crossing
  // Parity group per triangle: each closed connected shell is its own group, every open piece
  // shares group 0. A point is inside if it is inside any group (union of overlapping shells).
  std::vector<uint32_t> group;
  uint32_t groups = 1;
  static constexpr uint32_t kIgnored = UINT32_MAX;  // zero-volume closed sheets: no crossing
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }
};

namespace {

// An Embree scene of the soup's triangles `used` (every triangle when null), in float
// coordinates relative to `origin`, every hit reported to `filter`. Both oracles build theirs so.
RTCScene triangle_scene(const TriangleSoup& soup, const std::vector<uint32_t>* used, const Vec3& origin,
                        RTCFilterFunctionN filter) {
  RTCDevice device = shared_embree_device();
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                         3 * sizeof(float), soup.vertices.size()));
  for (size_t i = 0; i < soup.vertices.size(); ++i) {
    const Vec3 p = soup.vertices[i] - origin;
    vb[3 * i] = static_cast<float>(p.x);
    vb[3 * i + 1] = static_cast<float>(p.y);
    vb[3 * i + 2] = static_cast<float>(p.z);
  }
  const size_t n = used ? used->size() : soup.triangles.size();
  auto* ib = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) ib[3 * i + k] = soup.triangles[used ? (*used)[i] : i][k];
  rtcSetGeometryIntersectFilterFunction(geom, filter);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  if (const RTCError err = rtcGetDeviceError(device); err != RTC_ERROR_NONE) {
    rtcReleaseScene(scene);
    throw std::runtime_error("Embree scene build failed (error " + std::to_string(int(err)) + ")");
  }
  return scene;
}

// std::sort's order for a ray's few hits, without its set-up cost: insertion sort up to 16.
// Hits that compare equal are either the same (t, primitive) or, when sorted by (group, t),
// interchangeable for the crossing count, so the result is the same.
template <class Less>
void sort_hits(Hits& hits, Less less) {
  if (hits.size() > 16) {
    std::sort(hits.begin(), hits.end(), less);
    return;
  }
  for (size_t i = 1; i < hits.size(); ++i) {
    const auto h = hits[i];
    size_t j = i;
    for (; j > 0 && less(h, hits[j - 1]); --j) hits[j] = hits[j - 1];
    hits[j] = h;
  }
}

// Each primitive once (spatial splits can report one primitive twice), ordered by primitive.
void unique_by_primitive(Hits& hits) {
  if (hits.size() < 2) return;
  sort_hits(hits, [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second < b.second : a.first < b.first;
  });
  hits.erase(std::unique(hits.begin(), hits.end(),
                         [](const auto& a, const auto& b) { return a.second == b.second; }),
             hits.end());
}

// The triangles a ray from `from` (scene coordinates) along `dir` crosses, each once, as
// (t, primitive) ordered by primitive. The buffer is the thread's own and is reused by its next call.
Hits& ray_hits(RTCScene scene, const Vec3& from, const Vec3& dir) {
  thread_local Hits hits;
  hits.clear();
  CollectContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.hits[0] = &hits;
  RTCRayHit rh;
  rh.ray = make_ray(from, dir);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &ctx.base, &rh);
  unique_by_primitive(hits);
  return hits;
}

// The same for n <= 4 rays from one point, traced together as one Embree packet.
void ray_hits4(RTCScene scene, const Vec3& from, const Vec3* dirs, int n, std::array<Hits, 4>& hits) {
  CollectContext ctx;
  rtcInitIntersectContext(&ctx.base);
  alignas(16) int valid[4];
  alignas(16) RTCRayHit4 rh;
  for (int i = 0; i < 4; ++i) {
    hits[i].clear();
    ctx.hits[i] = &hits[i];
    valid[i] = i < n ? -1 : 0;
    const RTCRay r = make_ray(from, dirs[i < n ? i : 0]);
    rh.ray.org_x[i] = r.org_x;
    rh.ray.org_y[i] = r.org_y;
    rh.ray.org_z[i] = r.org_z;
    rh.ray.dir_x[i] = r.dir_x;
    rh.ray.dir_y[i] = r.dir_y;
    rh.ray.dir_z[i] = r.dir_z;
    rh.ray.tnear[i] = r.tnear;
    rh.ray.tfar[i] = r.tfar;
    rh.ray.mask[i] = r.mask;
    rh.ray.flags[i] = 0;
    rh.ray.time[i] = 0;
    rh.ray.id[i] = static_cast<unsigned>(i);
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect4(valid, scene, &ctx.base, &rh);
  for (int i = 0; i < n; ++i) unique_by_primitive(hits[i]);
}

}  // namespace

InsideOracle::InsideOracle(const TriangleSoup& soup, int rays, uint64_t seed)
    : impl_(std::make_unique<Impl>()), rays_(std::max(1, rays)), seed_(seed) {
  for (const auto& t : soup.triangles)
    for (uint32_t v : t) box_.add(soup.vertices.at(v));
  if (!box_.valid()) return;  // no triangles: everything is outside
  impl_->origin = box_.center();
  impl_->dedup_t = 1e-5 * std::max(box_.diagonal(), 1e-9);

  assign_groups(soup);
  impl_->scene = triangle_scene(soup, nullptr, impl_->origin, collect_filter);
}

namespace {

uint64_t edge_key(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

// Splits one closed connected component whose edges are not all shared by exactly two of its
// triangles (closed shells glued along edges, as in several Hong Kong inputs) into parity groups:
// each patch connected over 2-valent edges that is closed on its own is a group, and the rest of
// the component is one more group if it is closed too. Parity over the glued union would call the
// overlap of two shells outside; per shell it is inside some shell. Patches of (near) zero volume
// (doubled sheets) are returned as `ignored`. Returns false (no split) when that does not work out.
bool split_glued_shells(const TriangleSoup& soup, const std::vector<uint32_t>& tris,
                        std::vector<std::vector<uint32_t>>& groups, std::vector<uint32_t>& ignored) {
  std::unordered_map<uint64_t, std::vector<uint32_t>> edges;  // edge -> positions in `tris`
  for (uint32_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const auto& t = soup.triangles[tris[i]];
      edges[edge_key(t[k], t[(k + 1) % 3])].push_back(i);
    }
  bool glued = false;
  for (const auto& [key, ts] : edges) glued |= ts.size() > 2;
  if (!glued) return false;
  // Patches over 2-valent edges, with each triangle's orientation relative to its patch seed.
  const uint32_t n = static_cast<uint32_t>(tris.size());
  std::vector<uint32_t> patch(n, UINT32_MAX);
  std::vector<int8_t> flip(n, 0);
  auto dir = [&](uint32_t i, uint64_t key) {  // +1 if triangle i runs along the edge low -> high
    const auto& t = soup.triangles[tris[i]];
    for (int k = 0; k < 3; ++k)
      if (edge_key(t[k], t[(k + 1) % 3]) == key) return t[k] < t[(k + 1) % 3] ? 1 : -1;
    return 0;
  };
  std::vector<std::vector<uint32_t>> patches;
  for (uint32_t seed = 0; seed < n; ++seed) {
    if (patch[seed] != UINT32_MAX) continue;
    const uint32_t id = static_cast<uint32_t>(patches.size());
    patches.emplace_back();
    std::vector<uint32_t> stack{seed};
    patch[seed] = id;
    while (!stack.empty()) {
      const uint32_t i = stack.back();
      stack.pop_back();
      patches[id].push_back(i);
      const auto& t = soup.triangles[tris[i]];
      for (int k = 0; k < 3; ++k) {
        const uint64_t key = edge_key(t[k], t[(k + 1) % 3]);
        const auto& ts = edges[key];
        if (ts.size() != 2) continue;
        const uint32_t j = ts[0] == i ? ts[1] : ts[0];
        // Consistent neighbours run along their shared edge in opposite directions.
        const int8_t want = static_cast<int8_t>(dir(i, key) * (flip[i] ? -1 : 1) == dir(j, key) ? 1 : 0);
        if (patch[j] == UINT32_MAX) {
          patch[j] = id;
          flip[j] = want;
          stack.push_back(j);
        } else if (flip[j] != want) {
          return false;  // not orientable: leave the component to plain parity
        }
      }
    }
  }
  auto closed = [&](const std::vector<uint32_t>& ids) {
    std::unordered_map<uint64_t, int> count;
    for (uint32_t i : ids) {
      const auto& t = soup.triangles[tris[i]];
      for (int k = 0; k < 3; ++k) ++count[edge_key(t[k], t[(k + 1) % 3])];
    }
    for (const auto& [key, c] : count)
      if (c % 2) return false;
    return true;
  };
  std::vector<uint32_t> rest;
  double diag = 0;
  {
    BBox b;
    for (uint32_t t : tris)
      for (uint32_t v : soup.triangles[t]) b.add(soup.vertices[v]);
    diag = b.diagonal();
  }
  for (const auto& ids : patches) {
    if (!closed(ids)) {
      rest.insert(rest.end(), ids.begin(), ids.end());
      continue;
    }
    double vol = 0;  // signed volume with the patch's consistent orientation
    for (uint32_t i : ids) {
      const auto& t = soup.triangles[tris[i]];
      const Vec3 &a = soup.vertices[t[0]], &b = soup.vertices[t[1]], &c = soup.vertices[t[2]];
      vol += (flip[i] ? -1 : 1) * dot(a, cross(b, c)) / 6;
    }
    std::vector<uint32_t> g;
    for (uint32_t i : ids) g.push_back(tris[i]);
    if (std::abs(vol) <= 1e-9 * diag * diag * diag) ignored.insert(ignored.end(), g.begin(), g.end());
    else groups.push_back(std::move(g));
  }
  if (!rest.empty()) {
    if (!closed(rest)) return false;
    std::vector<uint32_t> g;
    for (uint32_t i : rest) g.push_back(tris[i]);
    groups.push_back(std::move(g));
  }
  return groups.size() > 1;
}

}  // namespace

void InsideOracle::assign_groups(const TriangleSoup& soup) {
  const size_t n = soup.triangles.size();
  UnionFind uf(n);
  auto find = [&](uint32_t x) { return uf.find(x); };
  std::unordered_map<uint64_t, std::vector<uint32_t>> edges;
  for (uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = soup.triangles[t][k], b = soup.triangles[t][(k + 1) % 3];
      auto& e = edges[edge_key(a, b)];
      if (!e.empty()) uf.link(t, e.front());
      e.push_back(t);
    }
  auto normal = [&](uint32_t t) {
    const auto& v = soup.vertices;
    const auto& tri = soup.triangles[t];
    const Vec3 c = cross(v[tri[1]] - v[tri[0]], v[tri[2]] - v[tri[0]]);
    const double len = norm(c);
    return len > 0 ? c / len : Vec3{};
  };
  const double wedge_cos = std::cos(kThinWedgeDegrees * M_PI / 180);
  std::vector<uint8_t> open(n, 0);
  for (const auto& [key, ts] : edges) {
    if (ts.size() % 2) open[find(ts.front())] = 1;
    if (ts.size() > 2) ++nonmanifold_edges_;
    // Two faces meeting at less than the angle, on the solid's side or the air's: their normals
    // are nearly opposite.
    if (ts.size() == 2 && dot(normal(ts[0]), normal(ts[1])) < -wedge_cos) thin_wedges_ = true;
  }
  std::map<uint32_t, std::vector<uint32_t>> closed_components;  // root -> triangles, ordered
  for (uint32_t t = 0; t < n; ++t)
    if (!open[find(t)]) closed_components[find(t)].push_back(t);
  impl_->group.assign(n, 0);
  impl_->groups = 1;
  bool split = false;
  for (const auto& [root, tris] : closed_components) {
    std::vector<std::vector<uint32_t>> shells;
    std::vector<uint32_t> ignored;
    if (split_glued_shells(soup, tris, shells, ignored)) {
      split = true;
      for (uint32_t t : ignored) impl_->group[t] = Impl::kIgnored;
    } else {
      shells = {tris};
    }
    for (const auto& shell : shells) {
      for (uint32_t t : shell) impl_->group[t] = impl_->groups;
      ++impl_->groups;
    }
  }
  // One closed shell (plus open pieces): plain parity over everything, so that doubled or
  // loose faces still merge with the shell's crossings within the merge distance.
  if (impl_->groups <= 2 && !split) {
    impl_->groups = 1;
    std::fill(impl_->group.begin(), impl_->group.end(), 0);
  }
}

void InsideOracle::set_merge_distance(double t) {
  if (t > 0) impl_->dedup_t = t;
}

InsideOracle::~InsideOracle() = default;

int InsideOracle::count_crossings(const Vec3& p, const Vec3& dir) const {
  return count_crossings(p, dir, nullptr);
}

int InsideOracle::count_crossings(const Vec3& p, const Vec3& dir, bool* clean) const {
  if (clean) *clean = impl_->groups == 1;
  if (!impl_->scene) return 0;
  return crossings(ray_hits(impl_->scene, p - impl_->origin, dir), dir, clean);
}

int InsideOracle::crossings(std::vector<std::pair<float, unsigned>>& hits, const Vec3& dir,
                            bool* clean) const {
  if (clean) *clean = impl_->groups == 1;
  // Hits at nearly equal t are merged below (shared edges and vertices, coincident triangles).
  if (hits.empty()) return 0;
  const double scale = 1.0 / norm(dir);  // t is in units of |dir|
  if (impl_->groups == 1) {
    sort_hits(hits, std::less<>());
    int count = 1;
    float last = hits[0].first;
    for (size_t i = 1; i < hits.size(); ++i) {
      const double gap = (hits[i].first - last) / scale;
      if (gap > impl_->dedup_t) ++count;
      // A gap near the merge distance: the ray went through an edge or vertex, or a thin slab.
      if (clean && gap <= 2 * impl_->dedup_t) *clean = false;
      last = hits[i].first;
    }
    return count;
  }
  // Several closed shells: crossings counted per parity group; the result is odd (inside) when
  // the point is inside any group.
  sort_hits(hits, [&](const auto& a, const auto& b) {
    const uint32_t ga = impl_->group[a.second], gb = impl_->group[b.second];
    return ga != gb ? ga < gb : a.first < b.first;
  });
  bool any_odd = false;
  for (size_t i = 0; i < hits.size();) {
    const uint32_t g = impl_->group[hits[i].second];
    if (g == Impl::kIgnored) break;  // sorted last
    int count = 1;
    float last = hits[i].first;
    size_t j = i + 1;
    for (; j < hits.size() && impl_->group[hits[j].second] == g; ++j) {
      if ((hits[j].first - last) / scale > impl_->dedup_t) ++count;
      last = hits[j].first;
    }
    any_odd |= (count & 1) != 0;
    i = j;
  }
  return any_odd ? 1 : 2;
}

uint64_t InsideOracle::splitmix_base(uint64_t point_id) const {
  return splitmix64(seed_ ^ splitmix64(point_id));
}

Vec3 InsideOracle::ray_direction(uint64_t base, int k) const {
  const uint64_t r1 = splitmix64(base + 2 * static_cast<uint64_t>(k));
  const uint64_t r2 = splitmix64(base + 2 * static_cast<uint64_t>(k) + 1);
  // Azimuths stratified over the circle; z = sin(elevation) uniform in [0.5, 1], i.e.
  // elevation 30°..90°, uniform over that spherical cap.
  const double phi = 2 * M_PI * (k + unit_double(r1)) / rays_;
  const double z = 0.5 + 0.5 * unit_double(r2);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  double sin_phi = 0, cos_phi = 0;
  fast_sincos(phi, sin_phi, cos_phi);
  return Vec3{r * cos_phi, r * sin_phi, z};
}

bool InsideOracle::inside(const Vec3& p, uint64_t point_id) const {
  if (!box_.valid() || p.x < box_.lo.x || p.y < box_.lo.y || p.z < box_.lo.z || p.x > box_.hi.x ||
      p.y > box_.hi.y || p.z > box_.hi.z)
    return false;
  const uint64_t base = splitmix_base(point_id);
  int votes = 0;
  // Once the majority is decided after `cast` rays: the same answer as all rays, since ray k's
  // direction depends only on (seed, point, k). Most points are unambiguous: 3 rays instead of 5.
  // 1 inside, 0 outside by parity, -1 not decided yet.
  auto decided = [&](int cast) {
    return 2 * votes > rays_ ? 1 : 2 * (votes + rays_ - cast) <= rays_ ? 0 : -1;
  };
  int k0 = 0;
  if (!valid_solid_ && impl_->scene) {
    // The first (rays + 1) / 2 rays are always cast (no majority before them), so they go to
    // Embree as one packet: they share their origin and the top of the BVH (docs/algorithm.md §6.1).
    const int first = std::min(4, (rays_ + 1) / 2);
    if (first >= 2) {
      Vec3 dirs[4];
      for (int k = 0; k < first; ++k) dirs[k] = ray_direction(base, k);
      thread_local std::array<Hits, 4> hits;
      ray_hits4(impl_->scene, p - impl_->origin, dirs, first, hits);
      for (int k = 0; k < first; ++k) {
        votes += crossings(hits[k], dirs[k], nullptr) & 1;
        if (const int d = decided(k + 1); d >= 0) return d == 1 || (enclosure_ && enclosed(p, point_id));
      }
      k0 = first;
    }
  }
  for (int k = k0; k < rays_; ++k) {
    bool clean = false;
    const int n = count_crossings(p, ray_direction(base, k), valid_solid_ && k == 0 ? &clean : nullptr) & 1;
    // A valid solid: a clean first ray decides the point; beside thin wedges a second clean ray
    // has to agree (docs/algorithm.md §6.6).
    if (clean && (!thin_wedges_ || rays_ < 3)) return n != 0;
    votes += n;
    if (clean) {
      bool clean1 = false;
      const int n1 = count_crossings(p, ray_direction(base, 1), &clean1) & 1;
      if (clean1 && n1 == n) return n != 0;
      votes += n1;
      k = 1;
    }
    if (const int d = decided(k + 1); d >= 0) return d == 1 || (enclosure_ && enclosed(p, point_id));
  }
  return enclosure_ && enclosed(p, point_id);
}

bool InsideOracle::enclosed(const Vec3& p, uint64_t point_id) const {
  if (!impl_->scene) return false;
  // Elevations from the zenith down to the horizon; the fan is turned per point (seeded) so
  // that a regular facade grid cannot line up with it everywhere.
  static constexpr double kElevationDeg[] = {90, 65, 40, 20, 5, 0};
  constexpr int kAzimuths = 16;
  const double turn = 2 * M_PI * unit_double(splitmix64(seed_ ^ splitmix64(~point_id))) / kAzimuths;
  const Vec3 o = p - impl_->origin;
  for (double elev : kElevationDeg) {
    const double e = elev * M_PI / 180, z = std::sin(e), r = std::cos(e);
    const int n = elev >= 90 ? 1 : kAzimuths;
    for (int k = 0; k < n; ++k) {
      const double phi = turn + 2 * M_PI * k / kAzimuths;
      RTCRay ray = make_ray(o, {r * std::cos(phi), r * std::sin(phi), z});
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      rtcOccluded1(impl_->scene, &ctx, &ray);
      if (ray.tfar >= 0) return false;  // not occluded: the ray escapes
    }
  }
  return true;
}

void InsideOracle::classify(const std::vector<Vec3>& pts, uint64_t first_id,
                            std::vector<uint8_t>& out) const {
  std::vector<uint64_t> ids(pts.size());
  for (size_t i = 0; i < ids.size(); ++i) ids[i] = first_id + i;
  classify(pts, ids, out);
}

void InsideOracle::classify(const std::vector<Vec3>& pts, const std::vector<uint64_t>& ids,
                            std::vector<uint8_t>& out) const {
  out.assign(pts.size(), 0);
  // Chunks of at least 16 points: a vote is 100–10,000 points, and coarser chunks leave one
  // thread idle while the other finishes a vote's last ones (docs/algorithm.md §6.1).
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pts.size(), 16),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) out[i] = inside(pts[i], ids[i]) ? 1 : 0;
                    }));
}

}  // namespace mc

namespace mc {

struct VerticalOracle::Impl {
  RTCScene scene = nullptr;
  Vec3 origin;
  double dedup_t = 0;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }
};

VerticalOracle::VerticalOracle(const TriangleSoup& soup, const std::vector<uint8_t>& cover, double merge_dist,
                               double ground_z)
    : impl_(std::make_unique<Impl>()), ground_z_(ground_z) {
  std::vector<uint32_t> used;
  for (uint32_t i = 0; i < soup.triangles.size(); ++i)
    if (i < cover.size() && cover[i]) {
      used.push_back(i);
      for (uint32_t v : soup.triangles[i]) box_.add(soup.vertices.at(v));
    }
  if (!box_.valid()) return;
  box_.lo.z = std::min(box_.lo.z, ground_z);
  impl_->origin = box_.center();
  impl_->dedup_t = std::max(merge_dist, 1e-5 * std::max(box_.diagonal(), 1e-9));
  impl_->scene = triangle_scene(soup, &used, impl_->origin, collect_filter);
}

VerticalOracle::~VerticalOracle() = default;

std::vector<double> VerticalOracle::crossings(double x, double y) const {
  std::vector<double> out;
  if (!impl_->scene) return out;
  const double z0 = box_.lo.z - 1.0;  // from below everything, upwards
  Hits& hits = ray_hits(impl_->scene, Vec3{x, y, z0} - impl_->origin, {0, 0, 1});
  if (hits.empty()) return out;
  std::sort(hits.begin(), hits.end());
  double last = -std::numeric_limits<double>::infinity();
  for (const auto& h : hits) {
    const double z = z0 + h.first;
    if (z - last > impl_->dedup_t) out.push_back(z);
    last = z;
  }
  return out;
}

bool VerticalOracle::inside(const Vec3& p) const {
  if (!box_.valid() || p.x < box_.lo.x || p.y < box_.lo.y || p.z < box_.lo.z || p.x > box_.hi.x ||
      p.y > box_.hi.y || p.z > box_.hi.z)
    return false;
  const std::vector<double> zs = crossings(p.x, p.y);
  size_t above = 0;
  for (double z : zs) above += z > p.z;
  return (above & 1) != 0;
}

void VerticalOracle::classify(const std::vector<Vec3>& pts, std::vector<uint8_t>& out) const {
  out.assign(pts.size(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pts.size(), 16),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) out[i] = inside(pts[i]) ? 1 : 0;
                    }));
}

double VerticalOracle::volume(int columns) const {
  if (!box_.valid()) return 0;
  const double wx = box_.hi.x - box_.lo.x, wy = box_.hi.y - box_.lo.y;
  if (!(wx > 0 && wy > 0)) return 0;
  const double step = std::sqrt(wx * wy / std::max(columns, 1));
  const int nx = std::max(1, static_cast<int>(std::ceil(wx / step)));
  const int ny = std::max(1, static_cast<int>(std::ceil(wy / step)));
  const double dx = wx / nx, dy = wy / ny;
  std::vector<double> col(static_cast<size_t>(nx) * ny, 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, col.size(), 64),
                    with_thread_tag([&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) {
                        // Column centres nudged off the grid so that they do not run along axis-aligned
                        // edges.
                        const double x = box_.lo.x + (static_cast<double>(i % nx) + 0.5 + 0.0123) * dx;
                        const double y = box_.lo.y + (static_cast<double>(i / nx) + 0.5 - 0.0171) * dy;
                        const std::vector<double> zs = crossings(x, y);
                        double len = 0;
                        size_t k = 0;
                        if (zs.size() % 2)
                          len += std::max(0.0, zs[k++] - ground_z_);  // open bottom: from the ground level
                        for (; k + 1 < zs.size(); k += 2) len += zs[k + 1] - zs[k];
                        col[i] = len;
                      }
                    }));
  double sum = 0;
  for (double v : col) sum += v;
  return sum * dx * dy;
}

}  // namespace mc
