#include "core/complex.hpp"

#include "core/stamped_table.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace mc {

namespace {
using K = CGAL::Exact_predicates_exact_constructions_kernel;

uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

// Double value of a lazy exact number, forcing exact evaluation when the interval is loose
// (vertices of nearly parallel planes).
double precise_double(const K::FT& x) {
  const auto iv = CGAL::to_interval(x);
  const double mid = 0.5 * (iv.first + iv.second);
  if (iv.second - iv.first <= 1e-12 * (std::abs(mid) + 1.0)) return mid;
  return CGAL::to_double(CGAL::exact(x));
}

int sign_of(CGAL::Oriented_side s) {
  return s == CGAL::ON_POSITIVE_SIDE ? 1 : (s == CGAL::ON_NEGATIVE_SIDE ? -1 : 0);
}
}  // namespace

struct CellComplex::Exact {
  struct EdgeInfo {
    uint32_t p1 = kNone, p2 = kNone;  // two distinct planes whose intersection is the edge line
    std::vector<uint32_t> facets;
  };
  std::vector<K::Plane_3> planes;
  std::vector<uint8_t> built;  // per plane: 0 not yet, 1 in progress, 2 done
  std::vector<K::Point_3> points;
  // The three planes each point was built from: it lies on them exactly, which decides its side
  // of those planes without evaluating the predicate (exactly on a plane, the interval filter
  // cannot decide and the exact evaluation is the split's main cost).
  std::vector<std::array<uint32_t, 3>> point_planes;
  std::unordered_map<uint64_t, EdgeInfo> edges;
  int side(uint32_t v, uint32_t plane) const {
    const auto& pp = point_planes[v];
    if (pp[0] == plane || pp[1] == plane || pp[2] == plane) return 0;
    return sign_of(planes[plane].oriented_side(points[v]));
  }
};

CellComplex::CellComplex(PlaneRegistry& planes, const BBox& box)
    : planes_(planes), exact_(std::make_unique<Exact>()) {
  if (!box.valid()) throw std::invalid_argument("cell complex: invalid bounding box");
  const uint32_t px[2] = {planes_.add({{1, 0, 0}, -box.lo.x}, PlaneOrigin::Box),
                          planes_.add({{1, 0, 0}, -box.hi.x}, PlaneOrigin::Box)};
  const uint32_t py[2] = {planes_.add({{0, 1, 0}, -box.lo.y}, PlaneOrigin::Box),
                          planes_.add({{0, 1, 0}, -box.hi.y}, PlaneOrigin::Box)};
  const uint32_t pz[2] = {planes_.add({{0, 0, 1}, -box.lo.z}, PlaneOrigin::Box),
                          planes_.add({{0, 0, 1}, -box.hi.z}, PlaneOrigin::Box)};
  ensure_planes();
  uint32_t c[2][2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) c[i][j][k] = add_vertex_from_planes(px[i], py[j], pz[k]);
  cells_.push_back(Cell{});
  // Loops have right-hand normal = +axis; the low face has the cell in front, the high behind.
  for (int i = 0; i < 2; ++i) {
    Facet f;
    f.plane = px[i];
    f.loop = {c[i][0][0], c[i][1][0], c[i][1][1], c[i][0][1]};
    (i == 0 ? f.front : f.back) = 0;
    cells_[0].facets.push_back(add_facet(std::move(f)));
  }
  for (int j = 0; j < 2; ++j) {
    Facet f;
    f.plane = py[j];
    f.loop = {c[0][j][0], c[0][j][1], c[1][j][1], c[1][j][0]};
    (j == 0 ? f.front : f.back) = 0;
    cells_[0].facets.push_back(add_facet(std::move(f)));
  }
  for (int k = 0; k < 2; ++k) {
    Facet f;
    f.plane = pz[k];
    f.loop = {c[0][0][k], c[1][0][k], c[1][1][k], c[0][1][k]};
    (k == 0 ? f.front : f.back) = 0;
    cells_[0].facets.push_back(add_facet(std::move(f)));
  }
}

CellComplex::~CellComplex() = default;

void CellComplex::ensure_planes() {
  auto& ep = exact_->planes;
  auto& built = exact_->built;
  const size_t first = ep.size();
  if (first == planes_.size()) return;
  ep.resize(planes_.size());
  built.resize(planes_.size(), 0);
  // An anchored plane goes exactly through the exact point of its three anchor planes (which
  // may come later in the registry); 1 = being built, to refuse a cyclic anchor.
  std::function<void(uint32_t)> build = [&](uint32_t id) {
    if (built[id] == 2) return;  // including every plane built by an earlier call
    if (built[id] == 1) throw std::logic_error("cell complex: cyclic plane anchor");
    built[id] = 1;
    const Plane& p = planes_[id];
    if (const auto* l = planes_.line_anchor(id)) {
      // Through the exact line of the two planes, spanned by it and the direction in the plane's
      // (double) normal plane across it, facing like that normal.
      build((*l)[0]);
      build((*l)[1]);
      auto res = CGAL::intersection(ep[(*l)[0]], ep[(*l)[1]]);
      const K::Line_3* line = res ? boost::get<K::Line_3>(&*res) : nullptr;
      if (!line) throw std::logic_error("cell complex: line anchor planes do not meet in a line");
      const K::Vector_3 u = line->to_vector(), n(p.n.x, p.n.y, p.n.z);
      const K::Point_3 o = line->point(0);
      K::Plane_3 pl(o, o + u, o + CGAL::cross_product(n, u));
      if (CGAL::is_negative(pl.orthogonal_vector() * n)) pl = pl.opposite();
      ep[id] = pl;
    } else if (const auto* a = planes_.anchor(id)) {
      for (uint32_t q : *a) build(q);
      auto res = CGAL::intersection(ep[(*a)[0]], ep[(*a)[1]], ep[(*a)[2]]);
      const K::Point_3* pt = res ? boost::get<K::Point_3>(&*res) : nullptr;
      if (!pt) throw std::logic_error("cell complex: anchor planes do not meet in a point");
      ep[id] = K::Plane_3(*pt, K::Vector_3(p.n.x, p.n.y, p.n.z));
    } else {
      ep[id] = K::Plane_3(p.n.x, p.n.y, p.n.z, p.d);
    }
    built[id] = 2;
  };
  for (uint32_t id = static_cast<uint32_t>(first); id < planes_.size(); ++id) build(id);
}

uint32_t CellComplex::add_vertex_from_planes(uint32_t p1, uint32_t p2, uint32_t p3) {
  const auto& ep = exact_->planes;
  auto res = CGAL::intersection(ep[p1], ep[p2], ep[p3]);
  const K::Point_3* pt = res ? boost::get<K::Point_3>(&*res) : nullptr;
  if (!pt) throw std::logic_error("cell complex: three planes do not meet in a point");
  exact_->points.push_back(*pt);
  exact_->point_planes.push_back({p1, p2, p3});
  points_.push_back({precise_double(pt->x()), precise_double(pt->y()), precise_double(pt->z())});
  return static_cast<uint32_t>(points_.size() - 1);
}

uint32_t CellComplex::add_facet(Facet f) {
  const uint32_t id = static_cast<uint32_t>(facets_.size());
  const size_t n = f.loop.size();
  for (size_t i = 0; i < n; ++i) {
    auto& e = exact_->edges[edge_key(f.loop[i], f.loop[(i + 1) % n])];
    e.facets.push_back(id);
    if (e.p1 == kNone) {
      e.p1 = f.plane;
    } else if (e.p2 == kNone && e.p1 != f.plane) {
      e.p2 = f.plane;
    }
  }
  facets_.push_back(std::move(f));
  return id;
}

void CellComplex::kill_facet(uint32_t id) {
  Facet& f = facets_[id];
  const size_t n = f.loop.size();
  for (size_t i = 0; i < n; ++i) {
    auto it = exact_->edges.find(edge_key(f.loop[i], f.loop[(i + 1) % n]));
    if (it == exact_->edges.end()) continue;
    auto& fs = it->second.facets;
    fs.erase(std::remove(fs.begin(), fs.end(), id), fs.end());
    // Keep the defining planes of edges still used elsewhere; forget unused edges.
    if (fs.empty()) exact_->edges.erase(it);
  }
  f.alive = false;
}

// Inserts vertex w between a and b in every facet using edge (a, b): keeps the complex
// conforming (no T-junctions in neighbouring cells).
void CellComplex::split_edge(uint32_t a, uint32_t b, uint32_t w) {
  auto it = exact_->edges.find(edge_key(a, b));
  if (it == exact_->edges.end()) throw std::logic_error("cell complex: unknown edge");
  Exact::EdgeInfo info = std::move(it->second);
  exact_->edges.erase(it);
  for (uint32_t g : info.facets) {
    auto& loop = facets_[g].loop;
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i) {
      const uint32_t u = loop[i], v = loop[(i + 1) % n];
      if ((u == a && v == b) || (u == b && v == a)) {
        loop.insert(loop.begin() + static_cast<long>(i + 1), w);
        break;
      }
    }
  }
  exact_->edges[edge_key(a, w)] = info;
  exact_->edges[edge_key(w, b)] = std::move(info);
}

int CellComplex::vertex_side(uint32_t v, uint32_t plane) const {
  const_cast<CellComplex*>(this)->ensure_planes();
  return exact_->side(v, plane);
}

bool CellComplex::collinear(uint32_t a, uint32_t b, uint32_t c) const {
  // Three vertices built on the same two planes lie on their line (two planes of one vertex meet
  // in a line), again without the predicate that exact collinearity makes expensive.
  const auto &pa = exact_->point_planes[a], &pb = exact_->point_planes[b], &pc = exact_->point_planes[c];
  int common = 0;
  for (uint32_t x : pa)
    common +=
        std::find(pb.begin(), pb.end(), x) != pb.end() && std::find(pc.begin(), pc.end(), x) != pc.end();
  if (common >= 2) return true;
  const auto& p = exact_->points;
  return CGAL::collinear(p[a], p[b], p[c]);
}

int CellComplex::cell_side(uint32_t c, uint32_t plane) const {
  return vertices_side(cell_vertices(c), plane);
}

int CellComplex::vertices_side(const std::vector<uint32_t>& vertices, uint32_t plane) const {
  bool pos = false, neg = false;
  for (uint32_t v : vertices) {
    const int s = vertex_side(v, plane);
    pos |= s > 0;
    neg |= s < 0;
    if (pos && neg) return 0;
  }
  return pos ? 1 : (neg ? -1 : 0);
}

std::optional<CellComplex::SplitResult> CellComplex::split(uint32_t c, uint32_t plane) {
  if (c >= cells_.size() || !cells_[c].alive) throw std::logic_error("cell complex: split of a dead cell");
  ensure_planes();
  VertexSides side;
  bool pos = false, neg = false;
  for (uint32_t v : cell_vertices(c)) {
    const int s = exact_->side(v, plane);
    side[v] = s;
    pos |= s > 0;
    neg |= s < 0;
  }
  if (!pos || !neg) return std::nullopt;
  const std::vector<uint32_t> old_facets = cells_[c].facets;
  cut_crossing_edges(old_facets, plane, side);
  const uint32_t cn = static_cast<uint32_t>(cells_.size());
  const uint32_t cp = cn + 1;
  cells_.push_back(Cell{});
  cells_.push_back(Cell{});
  cells_[cn].parent = cells_[cp].parent = c;
  std::unordered_map<uint32_t, uint32_t> cap_next;  // directed cap edges, outward for cn
  distribute_facets(c, old_facets, cn, cp, side, cap_next);
  add_section(plane, cn, cp, cap_next);
  Cell& old = cells_[c];
  old.alive = false;
  old.split_plane = plane;
  old.child_neg = cn;
  old.child_pos = cp;
  old.facets.clear();
  return SplitResult{cn, cp};
}

// Step 1: new vertices on crossing edges, propagated to every facet using those edges.
void CellComplex::cut_crossing_edges(const std::vector<uint32_t>& facets, uint32_t plane, VertexSides& side) {
  std::vector<std::pair<uint32_t, uint32_t>> crossing;
  for (uint32_t f : facets) {
    const auto& loop = facets_[f].loop;
    for (size_t i = 0; i < loop.size(); ++i) {
      const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      if (side[a] * side[b] < 0 && a < b) crossing.emplace_back(a, b);
      if (side[a] * side[b] < 0 && b < a) crossing.emplace_back(b, a);
    }
  }
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  for (auto [a, b] : crossing) {
    const auto& info = exact_->edges.at(edge_key(a, b));
    if (info.p2 == kNone) throw std::logic_error("cell complex: edge without two defining planes");
    const uint32_t w = add_vertex_from_planes(info.p1, info.p2, plane);
    side[w] = 0;
    split_edge(a, b, w);
  }
}

// Step 2: the cell's facets go to the children whole or split at the plane; the edges they leave
// on the plane are gathered for the section.
void CellComplex::distribute_facets(uint32_t c, const std::vector<uint32_t>& facets, uint32_t cn, uint32_t cp,
                                    const VertexSides& side,
                                    std::unordered_map<uint32_t, uint32_t>& cap_next) {
  auto side_of = [&](uint32_t v) {
    auto it = side.find(v);
    return it == side.end() ? 0 : it->second;
  };
  auto collect_cap_edges = [&](const std::vector<uint32_t>& outward) {
    for (size_t i = 0; i < outward.size(); ++i) {
      const uint32_t a = outward[i], b = outward[(i + 1) % outward.size()];
      if (side_of(a) == 0 && side_of(b) == 0) cap_next[b] = a;  // the cap runs the edge backwards
    }
  };
  auto attach = [&](uint32_t f, uint32_t to) {
    Facet& fa = facets_[f];
    if (fa.front == c) fa.front = to;
    else fa.back = to;
    cells_[to].facets.push_back(f);
  };
  // Replaces facet f in neighbour n's list by the given pieces.
  auto replace_in_neighbour = [&](uint32_t n, uint32_t f, uint32_t a, uint32_t b) {
    if (n == kNone) return;
    auto& fs = cells_[n].facets;
    auto it = std::find(fs.begin(), fs.end(), f);
    if (it == fs.end()) throw std::logic_error("cell complex: neighbour lost a facet");
    *it = a;
    fs.push_back(b);
  };
  for (uint32_t f : facets) {
    const std::vector<uint32_t> loop = facets_[f].loop;
    bool fp = false, fn = false;
    int zeros = 0;
    for (uint32_t v : loop) {
      fp |= side_of(v) > 0;
      fn |= side_of(v) < 0;
      zeros += side_of(v) == 0;
    }
    if (!fp && !fn) throw std::logic_error("cell complex: facet lies in the splitting plane");
    if (!fn) {
      attach(f, cp);
      continue;
    }
    if (!fp) {
      collect_cap_edges(outward_loop(f, c));
      attach(f, cn);
      continue;
    }
    if (zeros != 2) throw std::logic_error("cell complex: non-convex facet section");
    Facet lo, hi;
    lo.plane = hi.plane = facets_[f].plane;
    for (uint32_t v : loop) {
      if (side_of(v) <= 0) lo.loop.push_back(v);
      if (side_of(v) >= 0) hi.loop.push_back(v);
    }
    const bool c_in_front = facets_[f].front == c;
    const uint32_t other = c_in_front ? facets_[f].back : facets_[f].front;
    if (c_in_front) {
      lo.front = cn;
      hi.front = cp;
      lo.back = hi.back = other;
    } else {
      lo.back = cn;
      hi.back = cp;
      lo.front = hi.front = other;
    }
    kill_facet(f);
    const uint32_t flo = add_facet(std::move(lo));
    const uint32_t fhi = add_facet(std::move(hi));
    collect_cap_edges(outward_loop(flo, cn));
    cells_[cn].facets.push_back(flo);
    cells_[cp].facets.push_back(fhi);
    replace_in_neighbour(other, f, flo, fhi);
  }
}

// Step 3: the cap: the section polygon, chained from the directed edges gathered on the plane.
void CellComplex::add_section(uint32_t plane, uint32_t cn, uint32_t cp,
                              const std::unordered_map<uint32_t, uint32_t>& cap_next) {
  if (cap_next.size() < 3) throw std::logic_error("cell complex: degenerate section");
  uint32_t start = kNone;
  for (const auto& [a, b] : cap_next) start = std::min(start, a);
  Facet cap;
  cap.plane = plane;
  cap.front = cp;  // positive side of the plane
  cap.back = cn;   // loop is outward for cn, i.e. right-hand normal = +normal
  uint32_t v = start;
  do {
    cap.loop.push_back(v);
    auto it = cap_next.find(v);
    if (it == cap_next.end() || cap.loop.size() > cap_next.size())
      throw std::logic_error("cell complex: open section loop");
    v = it->second;
  } while (v != start);
  if (cap.loop.size() != cap_next.size()) throw std::logic_error("cell complex: section is not one loop");
  const uint32_t capf = add_facet(std::move(cap));
  cells_[cn].facets.push_back(capf);
  cells_[cp].facets.push_back(capf);
}

Vec3 CellComplex::outward_normal(uint32_t f, uint32_t c) const {
  const Vec3& n = planes_[facets_[f].plane].n;
  return facets_[f].back == c ? n : -n;
}

std::vector<uint32_t> CellComplex::outward_loop(uint32_t f, uint32_t c) const {
  std::vector<uint32_t> loop = facets_[f].loop;
  if (facets_[f].front == c) std::reverse(loop.begin(), loop.end());
  return loop;
}

std::vector<uint32_t> CellComplex::cell_vertices(uint32_t c) const {
  // Each vertex is on three or more of the cell's facets: it is taken once (a per-thread table by
  // vertex id) and only the distinct ones are sorted.
  thread_local StampedTable<bool> seen;
  seen.next_round(points_.size());
  std::vector<uint32_t> vs;
  for (uint32_t f : cells_[c].facets)
    for (const uint32_t v : facets_[f].loop)
      if (!seen.find(v)) {
        seen.set(v, true);
        vs.push_back(v);
      }
  std::sort(vs.begin(), vs.end());
  return vs;
}

void CellComplex::compute_cell_measures(uint32_t c) const {
  if (volume_.size() < cells_.size()) {
    volume_.resize(cells_.size(), 0.0);
    centroid_.resize(cells_.size());
    measured_.resize(cells_.size(), 0);
  }
  if (measured_[c]) return;
  // Fan tetrahedra from one vertex of the cell over every outward facet fan.
  const Vec3 o = points_[facets_[cells_[c].facets.front()].loop.front()];
  double vol = 0;
  Vec3 acc;
  for (uint32_t f : cells_[c].facets) {
    const auto loop = outward_loop(f, c);
    const Vec3 a = points_[loop[0]] - o;
    for (size_t i = 1; i + 1 < loop.size(); ++i) {
      const Vec3 b = points_[loop[i]] - o, d = points_[loop[i + 1]] - o;
      const double v6 = dot(a, cross(b, d));
      vol += v6;
      acc += (a + b + d) * (v6 / 4.0);
    }
  }
  volume_[c] = vol / 6.0;
  centroid_[c] = vol != 0 ? o + acc / vol : o;
  measured_[c] = 1;
}

double CellComplex::cell_volume(uint32_t c) const {
  compute_cell_measures(c);
  return volume_[c];
}

Vec3 CellComplex::cell_centroid(uint32_t c) const {
  compute_cell_measures(c);
  return centroid_[c];
}

BBox CellComplex::cell_bbox(uint32_t c) const {
  BBox b;
  for (uint32_t v : cell_vertices(c)) b.add(points_[v]);
  return b;
}

double CellComplex::facet_area(uint32_t f) const {
  const auto& loop = facets_[f].loop;
  Vec3 acc;
  for (size_t i = 1; i + 1 < loop.size(); ++i)
    acc += cross(points_[loop[i]] - points_[loop[0]], points_[loop[i + 1]] - points_[loop[0]]);
  return 0.5 * norm(acc);
}

void CellComplex::leaves(uint32_t c, std::vector<uint32_t>& out) const {
  std::vector<uint32_t> stack{c};
  while (!stack.empty()) {
    const uint32_t x = stack.back();
    stack.pop_back();
    if (cells_[x].alive) {
      out.push_back(x);
    } else {
      stack.push_back(cells_[x].child_pos);
      stack.push_back(cells_[x].child_neg);
    }
  }
}

std::vector<uint32_t> CellComplex::live_cells() const {
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < cells_.size(); ++i)
    if (cells_[i].alive) out.push_back(i);
  return out;
}

}  // namespace mc
