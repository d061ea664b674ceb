#include "core/surface.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <unordered_map>
#include <unordered_set>

namespace mc {

namespace {
uint64_t directed(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

// 2-D projection dropping the dominant axis of `n`, oriented so that CCW about n stays CCW.
struct Projector {
  int u, v;
  explicit Projector(const Vec3& n) {
    const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    u = (drop + 1) % 3;
    v = (drop + 2) % 3;
    if (n[drop] < 0) std::swap(u, v);
  }
};

double signed_area_2d(const std::vector<uint32_t>& ring, const CellComplex& cx, const Projector& pr) {
  double a = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec3& p = cx.point(ring[i]);
    const Vec3& q = cx.point(ring[(i + 1) % ring.size()]);
    a += p[pr.u] * q[pr.v] - q[pr.u] * p[pr.v];
  }
  return 0.5 * a;
}

bool point_in_ring(double x, double y, const std::vector<uint32_t>& ring, const CellComplex& cx,
                   const Projector& pr) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec3& a = cx.point(ring[i]);
    const Vec3& b = cx.point(ring[j]);
    if ((a[pr.v] > y) != (b[pr.v] > y)) {
      const double xi = a[pr.u] + (y - a[pr.v]) * (b[pr.u] - a[pr.u]) / (b[pr.v] - a[pr.v]);
      if (x < xi) in = !in;
    }
  }
  return in;
}
}  // namespace

std::vector<std::pair<uint32_t, uint32_t>> boundary_facets(const CellComplex& cx,
                                                           const std::vector<uint32_t>& cells) {
  std::unordered_set<uint32_t> in(cells.begin(), cells.end());
  std::vector<std::pair<uint32_t, uint32_t>> out;
  for (uint32_t c : cells) {
    for (uint32_t f : cx.cell(c).facets) {
      const uint32_t o = cx.other_side(f, c);
      if (o == CellComplex::kNone || !in.count(o)) out.emplace_back(f, c);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::map<uint64_t, std::vector<std::pair<uint32_t, uint32_t>>> boundary_edge_uses(
    const CellComplex& cx, const std::vector<uint32_t>& cells) {
  std::map<uint64_t, std::vector<std::pair<uint32_t, uint32_t>>> uses;
  for (auto [f, c] : boundary_facets(cx, cells)) {
    const auto& loop = cx.facet(f).loop;
    for (size_t k = 0; k < loop.size(); ++k) {
      const uint32_t a = loop[k], b = loop[(k + 1) % loop.size()];
      uses[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)].emplace_back(f, c);
    }
  }
  return uses;
}

namespace {

using EdgeGroups = std::map<std::tuple<uint32_t, bool, bool, uint32_t>, std::unordered_map<uint64_t, int>>;

// Step 1: directed boundary edges grouped by (plane, outward side, cut, neighbouring part); opposite
// pairs cancel, which merges coplanar facets into polygons (the complex is conforming, so
// edges match exactly).
EdgeGroups group_boundary_edges(const CellComplex& cx, const std::vector<uint32_t>& cells,
                                const std::vector<uint32_t>* solid, const LevelSurfaceContext& level) {
  EdgeGroups groups;
  for (auto [f, c] : boundary_facets(cx, cells)) {
    const bool plus = cx.facet(f).back == c;
    const uint32_t other = cx.other_side(f, c);
    const bool cut =
        solid && other != CellComplex::kNone && std::binary_search(solid->begin(), solid->end(), other);
    uint32_t neighbour = CellComplex::kNone;
    if (cut && level.part_of)
      if (auto it = level.part_of->find(other); it != level.part_of->end()) neighbour = it->second;
    auto& edges = groups[{cx.facet(f).plane, plus, cut, neighbour}];
    const auto loop = cx.outward_loop(f, c);
    for (size_t i = 0; i < loop.size(); ++i) {
      const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      auto rev = edges.find(directed(b, a));
      if (rev != edges.end()) {
        if (--rev->second == 0) edges.erase(rev);
      } else {
        ++edges[directed(a, b)];
      }
    }
  }
  return groups;
}

// A merged polygon of one plane, side, cut flag and neighbour: its loops before the straight
// vertices are dropped.
struct RawFace {
  uint32_t plane;
  bool plus, cut;
  uint32_t neighbour;
  std::vector<std::vector<uint32_t>> loops;
};

// Step 2: chain each group's edges into loops. Where the polygon touches itself at a vertex (two
// outgoing edges), the walk takes the sharpest left turn, so that every loop keeps the face
// on its left without crossing itself and the loops meet there corner to corner (any other
// pairing makes a ring that joins two separate fans of faces: not a 2-manifold vertex).
// Deterministic: walks start at the smallest vertex with a single outgoing edge if any.
std::vector<RawFace> chain_loops(const CellComplex& cx, EdgeGroups& groups) {
  std::vector<RawFace> raw;
  for (auto& [key, edges] : groups) {
    std::map<uint32_t, std::vector<uint32_t>> next;
    for (const auto& [e, n] : edges)
      for (int i = 0; i < n; ++i) next[uint32_t(e >> 32)].push_back(uint32_t(e & 0xffffffffu));
    for (auto& [a, bs] : next) std::sort(bs.begin(), bs.end(), std::greater<>());
    RawFace rf{std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key), {}};
    Vec3 normal = cx.planes()[rf.plane].n;
    if (!rf.plus) normal = -normal;
    const Projector pr(normal);
    auto turn = [&](uint32_t u, uint32_t v, uint32_t w) {  // signed angle u->v->w seen from outside
      const Vec3 &a = cx.point(u), &b = cx.point(v), &c = cx.point(w);
      const double dx1 = b[pr.u] - a[pr.u], dy1 = b[pr.v] - a[pr.v], dx2 = c[pr.u] - b[pr.u],
                   dy2 = c[pr.v] - b[pr.v];
      return std::atan2(dx1 * dy2 - dy1 * dx2, dx1 * dx2 + dy1 * dy2);
    };
    while (true) {
      auto it = std::find_if(next.begin(), next.end(), [](const auto& kv) { return kv.second.size() == 1; });
      if (it == next.end())
        it = std::find_if(next.begin(), next.end(), [](const auto& kv) { return !kv.second.empty(); });
      if (it == next.end()) break;
      const uint32_t start = it->first;
      std::vector<uint32_t> loop;
      uint32_t v = start;
      while (true) {
        auto& bs = next[v];
        if (bs.empty()) break;  // open chain: reported through the edge counts below
        size_t pick = bs.size() - 1;
        if (bs.size() > 1 && !loop.empty()) {
          double best = -10;
          for (size_t k = bs.size(); k-- > 0;) {
            const double t = turn(loop.back(), v, bs[k]);
            if (t > best + 1e-12) best = t, pick = k;
          }
        }
        loop.push_back(v);
        const uint32_t w = bs[pick];
        bs.erase(bs.begin() + static_cast<long>(pick));
        v = w;
        if (v == start) break;
      }
      if (loop.size() >= 3) rf.loops.push_back(std::move(loop));
    }
    raw.push_back(std::move(rf));
  }
  return raw;
}

// Step 3: drop vertices that lie in the middle of a straight edge shared by exactly two faces.
// Both edges at such a vertex lying on the same two planes, clearly not parallel, are on
// those planes' line: collinear without exact arithmetic (the complex's facets lie exactly
// on their planes).
// Otherwise the exact predicate decides (a bend between two faces of one plane).
std::unordered_set<uint32_t> straight_vertices(const CellComplex& cx, const std::vector<RawFace>& raw,
                                               const LevelSurfaceContext& level) {
  std::unordered_map<uint32_t, std::vector<uint32_t>> nbrs;
  std::unordered_map<uint64_t, std::vector<uint32_t>> edge_planes;  // undirected edge -> face planes
  for (const auto& rf : raw)
    for (const auto& loop : rf.loops)
      for (size_t i = 0; i < loop.size(); ++i) {
        const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
        nbrs[a].push_back(b);
        nbrs[b].push_back(a);
        edge_planes[directed(std::min(a, b), std::max(a, b))].push_back(rf.plane);
      }
  auto on_two_common_planes = [&](uint32_t a, uint32_t v, uint32_t b) {
    const auto& p = edge_planes[directed(std::min(a, v), std::max(a, v))];
    const auto& q = edge_planes[directed(std::min(v, b), std::max(v, b))];
    uint32_t first = CellComplex::kNone;
    for (uint32_t x : p)
      if (std::find(q.begin(), q.end(), x) != q.end()) {
        if (first == CellComplex::kNone) first = x;
        else if (x != first && norm(cross(cx.planes()[x].n, cx.planes()[first].n)) > 1e-9) return true;
      }
    return false;
  };
  std::unordered_set<uint32_t> drop;
  for (auto& [v, ns] : nbrs) {
    std::sort(ns.begin(), ns.end());
    ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
    if (ns.size() == 2 && !(level.keep && level.keep->count(v)) &&
        (on_two_common_planes(ns[0], v, ns[1]) || cx.collinear(ns[0], v, ns[1])))
      drop.insert(v);
  }
  return drop;
}

// Step 4: outer rings vs holes by orientation about the outward normal; holes go to their outer ring.
void rings_and_holes(const CellComplex& cx, std::vector<RawFace>& raw,
                     const std::unordered_set<uint32_t>& drop, Surface& s) {
  for (auto& rf : raw) {
    Vec3 n = cx.planes()[rf.plane].n;
    if (!rf.plus) n = -n;
    const Projector pr(n);
    std::vector<std::vector<uint32_t>> outers, holes;
    for (auto& loop : rf.loops) {
      std::vector<uint32_t> kept;
      for (uint32_t v : loop)
        if (!drop.count(v)) kept.push_back(v);
      if (kept.size() < 3) continue;
      (signed_area_2d(kept, cx, pr) >= 0 ? outers : holes).push_back(std::move(kept));
    }
    std::vector<SurfaceFace> faces;
    for (auto& o : outers) faces.push_back({{std::move(o)}, rf.plane, rf.plus, rf.cut, rf.neighbour});
    for (auto& h : holes) {
      size_t target = 0;
      if (faces.size() > 1) {
        const Vec3& p = cx.point(h[0]);
        for (size_t i = 0; i < faces.size(); ++i)
          if (point_in_ring(p[pr.u], p[pr.v], faces[i].rings[0], cx, pr)) target = i;
      }
      if (!faces.empty()) faces[target].rings.push_back(std::move(h));
    }
    for (auto& f : faces) s.faces.push_back(std::move(f));
  }
}

// Step 5: closedness and manifoldness of the merged surface.
void count_open_edges(Surface& s) {
  std::unordered_map<uint64_t, int> uses;
  for (const auto& f : s.faces)
    for (const auto& r : f.rings)
      for (size_t i = 0; i < r.size(); ++i) {
        uint32_t a = r[i], b = r[(i + 1) % r.size()];
        uses[directed(std::min(a, b), std::max(a, b))] += a < b ? 1 : 1000;
      }
  for (const auto& [e, n] : uses) {
    const int fwd = n % 1000, bwd = n / 1000;
    if (fwd != bwd) ++s.boundary_edges;
    if (fwd + bwd > 2) ++s.nonmanifold_edges;
  }
}

}  // namespace

// A driver over the five steps above (docs/algorithm.md §15).
Surface extract_surface(const CellComplex& cx, const std::vector<uint32_t>& cells,
                        const std::vector<uint32_t>* solid, const LevelSurfaceContext& level) {
  Surface s;
  EdgeGroups groups = group_boundary_edges(cx, cells, solid, level);
  std::vector<RawFace> raw = chain_loops(cx, groups);
  const std::unordered_set<uint32_t> drop = straight_vertices(cx, raw, level);
  s.dropped.assign(drop.begin(), drop.end());
  std::sort(s.dropped.begin(), s.dropped.end());
  rings_and_holes(cx, raw, drop, s);
  count_open_edges(s);
  return s;
}

void boundary_triangles(const CellComplex& cx, const std::vector<uint32_t>& cells, const Vec3& offset,
                        std::vector<Vec3>& vertices, std::vector<std::array<uint32_t, 3>>& triangles) {
  std::unordered_map<uint32_t, uint32_t> remap;
  auto index = [&](uint32_t v) {
    auto [it, fresh] = remap.emplace(v, static_cast<uint32_t>(vertices.size()));
    if (fresh) vertices.push_back(cx.point(v) + offset);
    return it->second;
  };
  for (auto [f, c] : boundary_facets(cx, cells)) {
    const auto loop = cx.outward_loop(f, c);
    for (size_t i = 1; i + 1 < loop.size(); ++i)
      triangles.push_back({index(loop[0]), index(loop[i]), index(loop[i + 1])});
  }
}

double surface_volume(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  double v = 0;
  for (uint32_t c : cells) v += cx.cell_volume(c);
  return v;
}

}  // namespace mc
