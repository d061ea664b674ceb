#include "core/part.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <map>
#include <numeric>
#include <span>
#include <unordered_map>

#include "core/hull.hpp"
#include "core/key_order.hpp"
#include "core/stamped_table.hpp"
#include "core/surface.hpp"
#include "core/union_find.hpp"

namespace mc {

uint64_t hash_bits(const Bits& b) {
  uint64_t h = 0x84222325cbf29ce4ULL;
  for (uint64_t w : b) {
    h ^= w + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0x100000001b3ULL;
  }
  return h;
}

size_t count_bits(const Bits& b) {
  size_t n = 0;
  for (uint64_t w : b) n += static_cast<size_t>(__builtin_popcountll(w));
  return n;
}

Bits CellSpace::all() const {
  Bits b(words(), 0);
  for (uint32_t i = 0; i < cells.size(); ++i) set_bit(b, i);
  return b;
}

CellSpace make_space(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  CellSpace s;
  s.cx = &cx;
  s.cells = cells;
  std::unordered_map<uint32_t, uint32_t> local;
  for (uint32_t i = 0; i < cells.size(); ++i) local[cells[i]] = i;
  s.sides.resize(cells.size());
  s.volume.resize(cells.size());
  s.vertices.resize(cells.size());
  for (uint32_t i = 0; i < cells.size(); ++i) {
    const uint32_t c = cells[i];
    for (uint32_t f : cx.cell(c).facets) {
      const uint32_t o = cx.other_side(f, c);
      auto it = o == CellComplex::kNone ? local.end() : local.find(o);
      s.sides[i].push_back({f, it == local.end() ? CellSpace::kOut : it->second});
    }
    s.volume[i] = cx.cell_volume(c);
    s.vertices[i] = cx.cell_vertices(c);
  }
  return s;
}

bool has_pinch_edge(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  const auto uses = boundary_edge_uses(cx, cells);
  for (const auto& [edge, facets] : uses)
    if (facets.size() > 2) return true;
  return !pinch_vertices(uses, [](const auto& fc) { return fc.first; }).empty();
}

std::vector<Bits> components(const CellSpace& s, const Bits& bits) {
  std::vector<Bits> out;
  Bits seen(bits.size(), 0);
  std::vector<uint32_t> stack;
  for (uint32_t i = 0; i < s.cells.size(); ++i) {
    if (!test_bit(bits, i) || test_bit(seen, i)) continue;
    Bits comp(bits.size(), 0);
    stack.assign(1, i);
    set_bit(seen, i);
    while (!stack.empty()) {
      const uint32_t c = stack.back();
      stack.pop_back();
      set_bit(comp, c);
      for (const auto& side : s.sides[c]) {
        const uint32_t o = side.other;
        if (o != CellSpace::kOut && test_bit(bits, o) && !test_bit(seen, o)) {
          set_bit(seen, o);
          stack.push_back(o);
        }
      }
    }
    out.push_back(std::move(comp));
  }
  return out;
}

namespace {

struct Incidence {
  uint32_t facet, cell;  // cell: global id
  uint32_t a, b;         // directed edge in the outward loop
  uint32_t face;         // the boundary facet's index in the part (0, 1, ...)
};

// A closed boundary (every edge used by exactly two faces) with V − E + F = 2 per connected
// component has no pinched vertex: unpinching a vertex of k fans adds k − 1 vertices and leaves a
// closed 2-manifold, whose Euler characteristic is at most 2 per component (docs/algorithm.md
// §9.2). So the fan test runs only for parts that fail this count (rings, pinches).
bool euler_says_no_pinch(const std::vector<std::pair<uint64_t, std::span<const Incidence>>>& by_edge,
                         size_t vertices, size_t faces, size_t& components) {
  components = 0;  // (not counted when an edge has other than two uses)
  UnionFind comp(faces);
  for (const auto& [key, inc] : by_edge) {
    if (inc.size() != 2) return false;
    comp.link(inc[0].face, inc[1].face);
  }
  for (uint32_t f = 0; f < faces; ++f) components += comp.is_root(f);
  const long chi = static_cast<long>(vertices) - static_cast<long>(by_edge.size()) + static_cast<long>(faces);
  return chi == 2 * static_cast<long>(components);
}

// One mesh edge between two boundary faces on different planes, with its dihedral angle.
struct DihedralEdge {
  uint32_t a, b;
  uint32_t p1, p2;  // p1 < p2
  Vec3 n1, n2;      // outward normals matching p1, p2
  double angle;
  bool reflex;
};

// Line through the intersection of two planes, closest to `near`.
bool plane_pair_line(const Plane& A, const Plane& B, const Vec3& near, Vec3& point, Vec3& dir) {
  const Vec3 u = cross(A.n, B.n);
  const double uu = dot(u, u);
  if (uu < 1e-12) return false;
  const double h1 = -A.d, h2 = -B.d;
  const Vec3 p0 = (cross(B.n, u) * h1 + cross(u, A.n) * h2) / uu;
  dir = u / std::sqrt(uu);
  point = p0 + dir * dot(near - p0, dir);
  return true;
}

struct RawLine {
  ConcaveLine line;
  bool reflex;
};

// Groups edges by (plane pair, reflex) and splits each group into chains of edges sharing vertices.
// Groups in key order, chains in the order of their union-find roots, edges in index order. The
// first edge of the group at each vertex is kept in a per-thread table by vertex id, a new round
// per group (core/stamped_table.hpp).
std::vector<RawLine> build_lines(const CellSpace& s, const std::vector<DihedralEdge>& edges,
                                 bool split_chains) {
  const PlaneRegistry& reg = s.cx->planes();
  auto key = [&](uint32_t i) { return std::make_tuple(edges[i].p1, edges[i].p2, edges[i].reflex); };
  std::vector<uint32_t> order(edges.size());
  std::iota(order.begin(), order.end(), uint32_t{0});
  std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) {
    const auto kx = key(x), ky = key(y);
    return kx != ky ? kx < ky : x < y;
  });
  thread_local StampedTable<uint32_t> first_at;  // per vertex: the group's first edge there
  UnionFind chain;
  std::vector<std::pair<uint32_t, uint32_t>> by_root;  // (root, edge in group)
  std::vector<size_t> members;
  std::vector<RawLine> out;
  for (size_t g = 0; g < order.size();) {
    size_t h = g;
    while (h < order.size() && key(order[h]) == key(order[g])) ++h;
    const uint32_t n = static_cast<uint32_t>(h - g);
    // Union-find over the group's edges through shared endpoints.
    chain.reset(n);
    first_at.next_round(s.cx->num_vertices());
    for (uint32_t k = 0; k < n; ++k) {
      for (uint32_t v : {edges[order[g + k]].a, edges[order[g + k]].b}) {
        if (const uint32_t* first = first_at.find(v)) chain.link(k, *first);
        else first_at.set(v, k);
        if (!split_chains) chain.link(k, 0);  // research-code grouping: one line per plane pair
      }
    }
    by_root.clear();
    for (uint32_t k = 0; k < n; ++k) by_root.emplace_back(chain.find(k), k);
    std::sort(by_root.begin(), by_root.end());
    const bool reflex = edges[order[g]].reflex;
    for (size_t c = 0; c < by_root.size();) {
      size_t d = c;
      members.clear();
      for (; d < by_root.size() && by_root[d].first == by_root[c].first; ++d)
        members.push_back(order[g + by_root[d].second]);
      c = d;
      const DihedralEdge& e0 = edges[members.front()];
      RawLine rl;
      rl.reflex = reflex;
      ConcaveLine& L = rl.line;
      L.p1 = e0.p1;
      L.p2 = e0.p2;
      L.n1 = e0.n1;
      L.n2 = e0.n2;
      double len_sum = 0, angle_sum = 0;
      for (size_t m : members) {
        const double len = norm(s.cx->point(edges[m].b) - s.cx->point(edges[m].a));
        len_sum += len;
        angle_sum += len * edges[m].angle;
      }
      L.angle = len_sum > 0 ? angle_sum / len_sum : e0.angle;
      if (!plane_pair_line(reg[L.p1], reg[L.p2], s.cx->point(e0.a), L.point, L.dir)) continue;
      L.t0 = 1e300;
      L.t1 = -1e300;
      for (size_t m : members)
        for (uint32_t v : {edges[m].a, edges[m].b}) {
          const double t = dot(s.cx->point(v) - L.point, L.dir);
          L.t0 = std::min(L.t0, t);
          L.t1 = std::max(L.t1, t);
        }
      out.push_back(rl);
    }
    g = h;
  }
  return out;
}

// Merges nearly coincident lines that share a plane (docs/algorithm.md §9.4): a small step
// (convex + reflex within δ) becomes a ≈180° line that is then dropped; two shallow reflex
// edges around a chamfer add up into one stronger line.
namespace {

// The extent [lo, hi] of line L along line M.
void extent_along(const ConcaveLine& L, const ConcaveLine& M, double& lo, double& hi) {
  const double s0 = dot(L.point + L.dir * L.t0 - M.point, M.dir);
  const double s1 = dot(L.point + L.dir * L.t1 - M.point, M.dir);
  lo = std::min(s0, s1);
  hi = std::max(s0, s1);
}

// The line that two concave lines sharing a plane merge into (their other planes' line over
// their common extent), or nothing: neither reflex, no shared plane, not parallel within 0.95,
// more than δ apart, or overlapping by δ or less.
std::optional<ConcaveLine> merged_line(const RawLine& r1, const RawLine& r2, const PlaneRegistry& reg,
                                       double delta) {
  const ConcaveLine& L1 = r1.line;
  const ConcaveLine& L2 = r2.line;
  if (!r1.reflex && !r2.reflex) return std::nullopt;
  // The plane the two lines share, and each line's other plane with its normal (the first
  // pairing in the order p1/p1, p1/p2, p2/p1, p2/p2).
  uint32_t b = 0, c = 0;
  Vec3 nb, nc;
  bool paired = false;
  for (int s1 = 0; s1 < 2 && !paired; ++s1)
    for (int s2 = 0; s2 < 2 && !paired; ++s2) {
      const uint32_t a1 = s1 ? L1.p2 : L1.p1, o1 = s1 ? L1.p1 : L1.p2;
      const uint32_t a2 = s2 ? L2.p2 : L2.p1, o2 = s2 ? L2.p1 : L2.p2;
      if (a1 != a2 || o1 == o2) continue;
      b = o1, nb = s1 ? L1.n1 : L1.n2;
      c = o2, nc = s2 ? L2.n1 : L2.n2;
      paired = true;
    }
  if (!paired) return std::nullopt;
  if (b == c || std::abs(dot(L1.dir, L2.dir)) < 0.95) return std::nullopt;
  const Vec3 mid2 = L2.point + L2.dir * (0.5 * (L2.t0 + L2.t1));
  const Vec3 off = mid2 - L1.point;
  if (norm(off - L1.dir * dot(off, L1.dir)) > delta) return std::nullopt;
  ConcaveLine M;
  const Vec3 mid1 = L1.point + L1.dir * (0.5 * (L1.t0 + L1.t1));
  if (!plane_pair_line(reg[b], reg[c], (mid1 + mid2) * 0.5, M.point, M.dir)) return std::nullopt;
  double a0, a1, b0, b1;
  extent_along(L1, M, a0, a1);
  extent_along(L2, M, b0, b1);
  M.t0 = std::max(a0, b0);
  M.t1 = std::min(a1, b1);
  if (M.t1 - M.t0 <= delta) return std::nullopt;
  M.p1 = std::min(b, c);
  M.p2 = std::max(b, c);
  M.n1 = b < c ? nb : nc;
  M.n2 = b < c ? nc : nb;
  M.angle = L1.angle + L2.angle - M_PI;
  return M;
}

// Appends the remainders of line `src` outside M's extent that are longer than δ, as they were.
void append_remainders(std::vector<RawLine>& lines, size_t src, const ConcaveLine& M, double delta) {
  double lo, hi;
  extent_along(lines[src].line, M, lo, hi);
  auto keep_piece = [&](double s0, double s1) {
    if (s1 - s0 <= delta) return;
    RawLine r = lines[src];
    const double u0 = dot(M.point + M.dir * s0 - r.line.point, r.line.dir);
    const double u1 = dot(M.point + M.dir * s1 - r.line.point, r.line.dir);
    r.line.t0 = std::min(u0, u1);
    r.line.t1 = std::max(u0, u1);
    lines.push_back(r);
  };
  keep_piece(lo, std::min(hi, M.t0));
  keep_piece(std::max(lo, M.t1), hi);
}

}  // namespace

namespace {

// The concave-line merge (merge_lines). Lines keep their index for the whole merge: a merged pair
// is marked dead and its replacements are appended, so the live lines in index order are the list
// a rebuilt vector would hold, and the plane index is built once (new lines go to `added_`).
class LineMerge {
 public:
  LineMerge(std::vector<RawLine>& lines, const PlaneRegistry& reg, double delta)
      : lines_(lines), reg_(reg), delta_(delta), alive_(lines.size(), 1), first_lines_(lines.size()) {
    for (size_t k = 0; k < lines.size(); ++k) {
      by_plane_.emplace_back(lines[k].line.p1, k);
      by_plane_.emplace_back(lines[k].line.p2, k);
    }
    std::sort(by_plane_.begin(), by_plane_.end());
    add_reach(0);
  }

  // Each pass looks for the first merging pair in (row, line) order. After a merge at row i every
  // pair of lines that were both there before and whose first line came before i was found not to
  // merge (a pure function of the two lines), so the rows before i only pair with the new lines:
  // only the rows that share a plane with a new line are tried, then every row from i on.
  void run() {
    size_t resume = 0;
    for (int guard = 0; guard < 1000; ++guard) {
      bool merged = false;
      if (resume > 0) {
        const size_t new_from = first_new_;
        for (const size_t r : rows_sharing_new_lines(resume))
          if (try_row(r, new_from)) {
            resume = r, merged = true;
            break;
          }
      }
      for (size_t i = resume; i < lines_.size() && !merged; ++i)
        if (alive_[i] && try_row(i, i + 1)) resume = i, merged = true;
      if (!merged) break;
    }
    size_t kept = 0;
    for (size_t k = 0; k < lines_.size(); ++k)
      if (alive_[k]) lines_[kept++] = std::move(lines_[k]);
    lines_.resize(kept);
  }

 private:
  // Per line, what merged_line tests first (its direction and its middle), kept compact: most
  // pairs on a plane are not parallel or lie more than δ apart, and are rejected from these alone.
  struct Reach {
    Vec3 point, dir, mid;
    bool reflex;
  };

  std::array<uint32_t, 2> planes_of(size_t k) const { return {lines_[k].line.p1, lines_[k].line.p2}; }

  void add_reach(size_t from) {
    for (size_t k = from; k < lines_.size(); ++k) {
      const ConcaveLine& l = lines_[k].line;
      reach_.push_back({l.point, l.dir, l.point + l.dir * (0.5 * (l.t0 + l.t1)), lines_[k].reflex});
    }
  }

  // The same rejections as merged_line's, on the same values.
  bool may_merge(size_t i, size_t j) const {
    const Reach &a = reach_[i], &b = reach_[j];
    if (std::abs(dot(a.dir, b.dir)) < 0.95) return false;
    const Vec3 off = b.mid - a.point;
    return !(norm(off - a.dir * dot(off, a.dir)) > delta_);
  }

  // Calls f(k) for every line k >= from on plane pl (the first lines, then the appended ones).
  template <class F>
  void for_lines_on(uint32_t pl, size_t from, F&& f) const {
    if (from < first_lines_)
      for (auto lo =
               std::lower_bound(by_plane_.begin(), by_plane_.end(), std::pair<uint32_t, size_t>{pl, from});
           lo != by_plane_.end() && lo->first == pl; ++lo)
        f(lo->second);
    if (auto it = added_.find(pl); it != added_.end())
      for (auto k = std::lower_bound(it->second.begin(), it->second.end(), from); k != it->second.end(); ++k)
        f(*k);
  }

  // The live rows before `resume` that share a plane with a line appended by the last merge.
  const std::vector<size_t>& rows_sharing_new_lines(size_t resume) {
    rows_.clear();
    for (size_t k = first_new_; k < lines_.size(); ++k)
      for (uint32_t pl : planes_of(k))
        for_lines_on(pl, 0, [&](size_t r) {
          if (r < resume && alive_[r]) rows_.push_back(r);
        });
    std::sort(rows_.begin(), rows_.end());
    rows_.erase(std::unique(rows_.begin(), rows_.end()), rows_.end());
    return rows_;
  }

  // Tries row i against the live lines from `from` on that share a plane with it, in index order;
  // two lines merge only if one of them is reflex (merged_line), so a convex row pairs only with
  // reflex lines. A merge marks both dead and appends the remainders and the merged line.
  bool try_row(size_t i, size_t from) {
    cand_.clear();
    const bool any = reach_[i].reflex;
    for (uint32_t pl : planes_of(i))
      for_lines_on(pl, from, [&](size_t k) {
        if (alive_[k] && (any || reach_[k].reflex) && may_merge(i, k)) cand_.push_back(k);
      });
    std::sort(cand_.begin(), cand_.end());
    cand_.erase(std::unique(cand_.begin(), cand_.end()), cand_.end());
    for (const size_t j : cand_) {
      const std::optional<ConcaveLine> M = merged_line(lines_[i], lines_[j], reg_, delta_);
      if (!M) continue;
      // Remainders of L1 and L2 outside the overlap, longer than δ, stay as they were; the
      // pieces and the merged line are appended.
      const size_t before = lines_.size();
      for (const size_t src : {i, j}) append_remainders(lines_, src, *M, delta_);
      lines_.push_back({*M, M->angle > M_PI});
      alive_[i] = alive_[j] = 0;
      alive_.resize(lines_.size(), 1);
      add_reach(before);
      for (size_t k = before; k < lines_.size(); ++k) {
        added_[lines_[k].line.p1].push_back(k);
        if (lines_[k].line.p2 != lines_[k].line.p1) added_[lines_[k].line.p2].push_back(k);
      }
      first_new_ = before;
      return true;
    }
    return false;
  }

  std::vector<RawLine>& lines_;
  const PlaneRegistry& reg_;
  double delta_;
  std::vector<uint8_t> alive_;
  std::vector<std::pair<uint32_t, size_t>> by_plane_;  // (plane, line) of the first lines, sorted
  size_t first_lines_;
  // The lines appended since, by plane (each list ascending): rows scan only their planes' lists.
  std::unordered_map<uint32_t, std::vector<size_t>> added_;
  std::vector<Reach> reach_;
  std::vector<size_t> cand_, rows_;
  size_t first_new_ = 0;  // the first line appended by the last merge
};

}  // namespace

void merge_lines(std::vector<RawLine>& lines, const PlaneRegistry& reg, double delta) {
  LineMerge(lines, reg, delta).run();
}

// The hull's facets that a ray along unit b leaves through (n·b > 0), with n·b: computed once
// for all the points of a line.
struct FacingFacets {
  std::vector<std::pair<const Plane*, double>> facets;
  FacingFacets(const std::vector<Plane>& hull, const Vec3& b) {
    for (const Plane& f : hull) {
      const double nb = dot(f.n, b);
      if (nb > 1e-12) facets.emplace_back(&f, nb);
    }
  }
  // Distance from s along b to the boundary of the convex hull (closed form over facets).
  double exit_distance(const Vec3& s) const {
    double t = 1e300;
    for (const auto& [f, nb] : facets) t = std::min(t, std::max(0.0, -f->signed_distance(s) / nb));
    return t == 1e300 ? 0.0 : t;
  }
};

}  // namespace

namespace {

// The part's boundary facets (docs/algorithm.md §9.2): its volume and cell count, every boundary
// edge use (edge key, incidence) in boundary order and every boundary facet corner
// (vertex << 32 | plane). Returns the number of boundary facets.
uint32_t part_boundary(const CellSpace& s, PartAnalysis& info,
                       std::vector<std::pair<uint64_t, Incidence>>& edge_uses,
                       std::vector<uint64_t>& vertex_planes) {
  const CellComplex& cx = *s.cx;
  uint32_t faces = 0;
  for_each_bit(info.bits, [&](uint32_t i) {
    ++info.cell_count;
    info.volume += s.volume[i];
    for (const auto& side : s.sides[i]) {
      if (side.other != CellSpace::kOut && test_bit(info.bits, side.other)) continue;
      // The facet's loop as outward_loop() gives it (reversed when the cell is in front), read in place.
      const auto& facet = cx.facet(side.facet);
      const auto& loop = facet.loop;
      const size_t n = loop.size();
      const bool reversed = facet.front == s.cells[i];
      auto at = [&](size_t k) { return reversed ? loop[n - 1 - k] : loop[k]; };
      for (size_t k = 0; k < n; ++k) {
        const uint32_t a = at(k), b = at((k + 1) % n);
        edge_uses.push_back(
            {(uint64_t(std::min(a, b)) << 32) | std::max(a, b), {side.facet, s.cells[i], a, b, faces}});
        vertex_planes.push_back((uint64_t(a) << 32) | facet.plane);
      }
      ++faces;
    }
  });
  return faces;
}

// Hull points: the boundary vertices where three or more planes meet. A vertex whose boundary
// facets lie on one plane is inside a flat face, and one on two planes is inside their common
// edge line; neither is an extreme point, so the hull is the same without them
// (docs/algorithm.md §9.2), and the hull is most of the analysis' time. `vertices` counts the
// boundary vertices. Each corner is looked up in a per-thread table by vertex id holding the
// first two planes seen (core/stamped_table.hpp): linear in the corners, which sorting them is
// not (a tenth of the analysis). Returns the hull points' vertex ids, unordered: a convex part
// needs only the count (hull_input orders them).
std::vector<uint32_t> hull_vertices(const CellComplex& cx, const std::vector<uint64_t>& vertex_planes,
                                    size_t& vertices) {
  struct Planes {
    uint32_t plane[2];
    uint32_t count;
  };
  thread_local StampedTable<Planes> seen;
  seen.next_round(cx.num_vertices());
  std::vector<uint32_t> corners;
  vertices = 0;
  for (const uint64_t vp : vertex_planes) {
    const uint32_t v = static_cast<uint32_t>(vp >> 32), plane = static_cast<uint32_t>(vp);
    Planes* e = seen.find(v);
    if (!e) {
      seen.set(v, {{plane, 0}, 1});
      ++vertices;
    } else if (e->count == 1 && plane != e->plane[0]) {
      e->plane[1] = plane, e->count = 2;
    } else if (e->count == 2 && plane != e->plane[0] && plane != e->plane[1]) {
      e->count = 3;
      corners.push_back(v);
    }
  }
  return corners;
}

// The hull's input: the hull vertices' points in vertex id order.
std::vector<Vec3> hull_input(const CellComplex& cx, std::vector<uint32_t> corners) {
  std::sort(corners.begin(), corners.end());
  std::vector<Vec3> pts;
  pts.reserve(corners.size());
  for (uint32_t v : corners) pts.push_back(cx.point(v));
  return pts;
}

// Dihedral edges between boundary faces on different planes (2-manifold edges only), their
// angles not yet measured (dihedral_angles); pinch edges and pinch vertices counted into
// info.pinch_edges.
std::vector<DihedralEdge> dihedral_edges(const CellComplex& cx,
                                         const std::vector<std::pair<uint64_t, Incidence>>& edge_uses,
                                         size_t vertices, uint32_t faces, PartAnalysis& info,
                                         size_t& components) {
  std::vector<DihedralEdge> edges;
  // The uses of each edge, edges in key order (deterministic), uses in boundary order.
  const std::vector<uint32_t> order = stable_key_order(
      static_cast<uint32_t>(edge_uses.size()), [&](uint32_t i) { return edge_uses[i].first; },
      cx.num_vertices());
  std::vector<Incidence> uses;
  uses.reserve(edge_uses.size());
  for (const uint32_t i : order) uses.push_back(edge_uses[i].second);
  std::vector<std::pair<uint64_t, std::span<const Incidence>>> by_edge;
  for (size_t i = 0; i < order.size();) {
    const uint64_t key = edge_uses[order[i]].first;
    size_t j = i;
    while (j < order.size() && edge_uses[order[j]].first == key) ++j;
    by_edge.emplace_back(key, std::span<const Incidence>(uses.data() + i, j - i));
    i = j;
  }
  for (const auto& [key, inc] : by_edge) {
    if (inc.size() > 2) ++info.pinch_edges;
    if (inc.size() != 2) continue;
    const uint32_t pa = cx.facet(inc[0].facet).plane, pb = cx.facet(inc[1].facet).plane;
    if (pa == pb) continue;
    const Vec3 N1 = cx.outward_normal(inc[0].facet, inc[0].cell);
    const Vec3 N2 = cx.outward_normal(inc[1].facet, inc[1].cell);
    const Vec3 e = normalized(cx.point(inc[0].b) - cx.point(inc[0].a));
    const Vec3 u1 = cross(N1, e);  // into face 1 (loops are CCW seen from outside)
    const bool reflex = dot(u1, N2) > 0;
    DihedralEdge d{
        inc[0].a, inc[0].b, std::min(pa, pb), std::max(pa, pb), pa < pb ? N1 : N2, pa < pb ? N2 : N1,
        0,        reflex};
    edges.push_back(d);
  }
  // A vertex where two fans of faces meet is as invalid in a solid as a pinch edge.
  if (!euler_says_no_pinch(by_edge, vertices, faces, components))
    info.pinch_edges +=
        static_cast<int>(pinch_vertices(by_edge, [](const Incidence& x) { return x.facet; }).size());
  return edges;
}

// The dihedral angles, once the part is known not to be convex (a convex part needs only which
// edges are reflex).
void dihedral_angles(std::vector<DihedralEdge>& edges) {
  for (DihedralEdge& d : edges) {
    const double c = std::clamp(dot(d.n1, d.n2), -1.0, 1.0);
    d.angle = d.reflex ? M_PI + std::acos(c) : M_PI - std::acos(c);
  }
}

// Reflex lines above the concavity threshold, weighted by length x depth into the hull.
void weigh_lines(std::vector<RawLine>& raw, const Hull& hull, const AnalysisContext& ctx,
                 PartAnalysis& info) {
  const DecomposeParams& dec = *ctx.dec;
  const double min_angle = dec.concave_thresh * M_PI + 1e-6;
  const double floor = 1e-6 * ctx.a_diag;
  for (RawLine& r : raw) {
    ConcaveLine& L = r.line;
    if (L.angle < min_angle || L.length() <= 0) continue;
    const Vec3 b = normalized(L.n1 + L.n2);
    const FacingFacets facing(hull.facets, b);
    const int n = std::clamp(static_cast<int>(L.length() / std::max(ctx.dist, 1e-12)), 2, 16);
    double dmax = 0, dsum = 0;
    for (int k = 0; k <= n; ++k) {
      const Vec3 sp = L.point + L.dir * (L.t0 + (L.t1 - L.t0) * k / n);
      const double d = facing.exit_distance(sp);
      dmax = std::max(dmax, d);
      dsum += d;
    }
    L.weight = L.length() * (dec.significance_max ? dmax : dsum / (n + 1));
    if (L.weight >= floor) info.lines.push_back(L);
  }
}

// Candidate planes of the significant lines (docs/algorithm.md §10).
void candidate_planes(const AnalysisContext& ctx, const PlaneResolver& resolve, const PlaneRegistry& reg,
                      double sig, PartAnalysis& info) {
  const DecomposeParams& dec = *ctx.dec;
  std::vector<std::pair<uint32_t, double>> cands;  // plane id, accumulated weight
  auto add = [&](uint32_t id, double w) {
    for (auto& c : cands)
      if (c.first == id) {
        c.second += w;
        return;
      }
    cands.emplace_back(id, w);
  };
  const Vec3 up{0, 0, 1};
  std::vector<uint32_t> pool;
  for (const auto& L : info.lines) {
    if (L.weight < sig) break;
    add(L.p1, L.weight);
    add(L.p2, L.weight);
  }
  for (const auto& c : cands) pool.push_back(c.first);
  for (const auto& L : info.lines) {
    if (L.weight < sig) break;
    const PlaneClass c1 = classify_plane(reg[L.p1], ctx.angle_rad),
                     c2 = classify_plane(reg[L.p2], ctx.angle_rad);
    const bool horizontal_line = std::abs(L.dir.z) <= 0.1;
    auto is = [&](PlaneClass a, PlaneClass b) { return (c1 == a && c2 == b) || (c1 == b && c2 == a); };
    std::vector<Plane> extra;
    const Vec3 mid = L.point + L.dir * (0.5 * (L.t0 + L.t1));
    auto vertical_through_line = [&] {
      const Vec3 n = cross(L.dir, up);
      if (norm(n) > 1e-6) extra.push_back({normalized(n), -dot(normalized(n), mid)});
    };
    if (!horizontal_line) {
      if (is(PlaneClass::Vertical, PlaneClass::Vertical) && dec.with_bisector) {
        const Vec3 n = L.n1 - L.n2;  // bisector through the material of the reflex angle
        if (norm(n) > 1e-9) extra.push_back({normalized(n), -dot(normalized(n), mid)});
      } else if (is(PlaneClass::Inclined, PlaneClass::Inclined)) {
        vertical_through_line();
      }
    } else {
      if (is(PlaneClass::Horizontal, PlaneClass::Inclined) ||
          is(PlaneClass::Horizontal, PlaneClass::Horizontal)) {
        vertical_through_line();
      } else if (is(PlaneClass::Inclined, PlaneClass::Inclined)) {
        extra.push_back({up, -mid.z});
        vertical_through_line();
      }
    }
    for (const Plane& p : extra) {
      if (auto id = resolve(p, pool)) {
        if (std::find(pool.begin(), pool.end(), *id) == pool.end()) pool.push_back(*id);
        add(*id, L.weight);
      }
    }
  }
  std::stable_sort(cands.begin(), cands.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second > b.second : a.first < b.first;
  });
  for (const auto& [id, w] : cands) {
    const PlaneClass pc = classify_plane(reg[id], ctx.angle_rad);
    const std::string& m = dec.cut_mode;
    const bool keep = m == "A" || (m == "H" && pc == PlaneClass::Horizontal) ||
                      (m == "V" && pc == PlaneClass::Vertical) || (m == "HV" && pc != PlaneClass::Inclined) ||
                      (m == "HI" && pc != PlaneClass::Vertical) ||
                      (m == "VI" && pc != PlaneClass::Horizontal);
    if (keep) info.candidates.push_back(id);
    if (dec.max_candidates > 0 && static_cast<int>(info.candidates.size()) >= dec.max_candidates) break;
  }
}

}  // namespace

PartAnalysis analyze_part(const CellSpace& s, Bits bits, const AnalysisContext& ctx,
                          const PlaneResolver& resolve) {
  const CellComplex& cx = *s.cx;
  const PlaneRegistry& reg = cx.planes();
  const DecomposeParams& dec = *ctx.dec;
  PartAnalysis info;
  info.bits = std::move(bits);
  info.hash = hash_bits(info.bits);

  std::vector<std::pair<uint64_t, Incidence>> edge_uses;  // (edge key, use) in boundary order
  std::vector<uint64_t> vertex_planes;  // (vertex << 32 | plane) of every boundary facet corner
  const uint32_t faces = part_boundary(s, info, edge_uses, vertex_planes);
  size_t vertices = 0;
  std::vector<uint32_t> corners = hull_vertices(cx, vertex_planes, vertices);
  size_t components = 0;  // of the boundary surface
  std::vector<DihedralEdge> edges = dihedral_edges(cx, edge_uses, vertices, faces, info, components);
  // One closed boundary surface without pinches whose every edge is convex bounds a convex solid:
  // its hull is itself (Δ = 0), and it has no concave line: its lines are all convex, and only
  // lines above concave_thresh · π (> π) count, or merged ones, which need a reflex line. Most of
  // a search's pieces are such (docs/algorithm.md §9.2).
  if (components == 1 && info.pinch_edges == 0 &&
      std::none_of(edges.begin(), edges.end(), [](const DihedralEdge& e) { return e.reflex; })) {
    info.hull_volume = info.volume;
    return info;
  }
  const std::vector<Vec3> pts = hull_input(cx, std::move(corners));
  const std::shared_ptr<const Hull> hull_ptr =
      ctx.hulls ? ctx.hulls->get(pts) : std::make_shared<const Hull>(convex_hull(pts));
  const Hull& hull = *hull_ptr;
  info.hull_volume = hull.volume;
  info.delta = std::max(0.0, info.hull_volume - info.volume);
  if (info.delta <= 1e-9 * std::max(info.volume, 1e-300)) info.delta = 0;

  dihedral_angles(edges);
  std::vector<RawLine> raw = build_lines(s, edges, dec.split_chains);
  merge_lines(raw, reg, ctx.dist);
  weigh_lines(raw, hull, ctx, info);
  std::stable_sort(info.lines.begin(), info.lines.end(),
                   [](const ConcaveLine& a, const ConcaveLine& b) { return a.weight > b.weight; });
  info.e_all = static_cast<int>(info.lines.size());
  const double sig = ctx.level * ctx.a_diag;
  for (const auto& L : info.lines) info.e_sig += L.weight >= sig;
  if (info.delta > 0 && info.volume >= dec.cvx_thresh * info.hull_volume) {
    // Convex enough (cvx_thresh): what is left are dents a planner would not cut at.
    info.nearly_convex = true;
    info.lines.clear();
    info.e_all = info.e_sig = 0;
    info.delta = 0;
    return info;
  }
  candidate_planes(ctx, resolve, reg, sig, info);
  return info;
}

}  // namespace mc
