#include "core/hashing.hpp"
#include "core/carve.hpp"

#include "core/surface.hpp"
#include "core/thread_tag.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <tuple>
#include <unordered_set>

namespace mc {

namespace {

enum class Crossing { No, Hair, Yes };

// A vertex on the padded carving box: never part of the output (the box lies beyond the input).
bool on_outer_box(const Vec3& v, const BBox& outer) {
  return v.x == outer.lo.x || v.x == outer.hi.x || v.y == outer.lo.y || v.y == outer.hi.y ||
         v.z == outer.lo.z || v.z == outer.hi.z;
}

// A plane passing within δ/10 of a vertex without going through it would create vertices a hair
// apart (they collapse when the output is quantised). Vertices on the padded box do not count:
// they never reach the output (and a plane of the building may well pass near the box's corner
// lines by the box's own round numbers).
struct HairTest {
  double on, hair;
  const BBox& outer;
  HairTest(const Plane& pl, double hair_distance, const BBox& box)
      : on(1e-9 * (1 + std::abs(pl.d))), hair(hair_distance), outer(box) {}
  // `dist`: the vertex's unsigned distance from the plane.
  bool operator()(double dist, const Vec3& v) const {
    return dist > on && dist < hair && !on_outer_box(v, outer);
  }
};

// A live cell's vertices and their box, gathered once for the tests of all its planes.
struct CellVertices {
  std::vector<uint32_t> ids;
  BBox box;
  CellVertices(const CellComplex& cx, uint32_t c) : ids(cx.cell_vertices(c)) {
    for (uint32_t v : ids) box.add(cx.point(v));
  }
};

// Does plane q really cross cell c: a vertex beyond δ on both sides and the region nearby.
// `No` also holds for every sub-cell of c (the plane can be dropped for them); `Hair` only for
// this cell (a vertex a hair from the plane, which a later split may remove: keep the plane).
Crossing crosses(const CellComplex& cx, const CellVertices& c, const CarvePlane& q, double delta,
                 double hair_distance, const BBox& outer) {
  if (!c.box.overlaps(q.bbox, 3 * delta)) return Crossing::No;
  const Plane& pl = cx.planes()[q.plane];
  const HairTest hair(pl, hair_distance, outer);
  bool pos = false, neg = false, near = false;
  for (uint32_t v : c.ids) {
    const double s = pl.signed_distance(cx.point(v));
    pos |= s > delta;
    neg |= s < -delta;
    near |= hair(std::abs(s), cx.point(v));
  }
  if (!(pos && neg)) return Crossing::No;
  return near ? Crossing::Hair : Crossing::Yes;
}

constexpr double kHairCutShare = 0.2;

// The smallest distance from plane q of the vertices of cell c that lie a hair from it (see
// `HairTest`); +inf when there is none.
double hair_gap(const CellComplex& cx, const CellVertices& c, const CarvePlane& q, double hair_distance,
                const BBox& outer) {
  const Plane& pl = cx.planes()[q.plane];
  const HairTest hair(pl, hair_distance, outer);
  double gap = std::numeric_limits<double>::infinity();
  for (uint32_t v : c.ids) {
    const double s = std::abs(pl.signed_distance(cx.point(v)));
    if (hair(s, cx.point(v))) gap = std::min(gap, s);
  }
  return gap;
}

// The planes of a live cell's facets, oriented outward: the cell is {x : n·x + d <= 0 for each}.
std::vector<Plane> outward_planes(const CellComplex& cx, uint32_t c) {
  std::vector<Plane> outward;
  for (uint32_t f : cx.cell(c).facets) {
    Plane pl = cx.planes()[cx.facet(f).plane];
    if (dot(pl.n, cx.outward_normal(f, c)) < 0) pl = Plane{-pl.n, -pl.d};
    outward.push_back(pl);
  }
  return outward;
}

// Uniform point in tetrahedron (a, b, c, d) from a point of the unit cube (Rocchini-Cignoni fold).
Vec3 fold_to_tet(double s, double t, double u, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (s + t > 1) {
    s = 1 - s;
    t = 1 - t;
  }
  if (t + u > 1) {
    const double tmp = u;
    u = 1 - s - t;
    t = 1 - tmp;
  } else if (s + t + u > 1) {
    const double tmp = u;
    u = s + t + u - 1;
    s = 1 - t - tmp;
  }
  return a + (b - a) * s + (c - a) * t + (d - a) * u;
}

}  // namespace

namespace {

// A range of a region vote's point order: untouched (`uniform`: `batch` representatives decide
// every point when they agree) or near the surface (every point classified).
struct RegionLeaf {
  uint32_t begin, end;
  bool uniform;
};

// The tight box of the points order[begin, end).
BBox points_box(const std::vector<Vec3>& pts, const std::vector<uint32_t>& order, uint32_t begin,
                uint32_t end) {
  BBox b;
  b.lo = b.hi = pts[order[begin]];
  for (uint32_t k = begin + 1; k < end; ++k) {
    const Vec3& v = pts[order[k]];
    b.lo = {std::min(b.lo.x, v.x), std::min(b.lo.y, v.y), std::min(b.lo.z, v.z)};
    b.hi = {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y), std::max(b.hi.z, v.z)};
  }
  return b;
}

// Step 1: the regions, one level of boxes at a time. Permutes `order` so that every leaf is a
// range of it. The points are split by the midpoint of their box's longest side; each box tests
// only the triangles that touched its parent, so the tree is queried once per cell
// (docs/design.md "Regions, not points"). Each box partitions only its own range, so the leaves
// and the order are the same whatever order the boxes are split in.
class RegionSplit {
 public:
  RegionSplit(const std::vector<Vec3>& pts, size_t batch, const SurfaceIndex& surface,
              std::vector<uint32_t> triangles, double slab, const BBox& oracle_box,
              std::vector<uint32_t>& order)
      : pts_(pts), batch_(batch), surface_(surface), slab_(slab), oracle_box_(oracle_box), order_(order) {
    lists_.push_back(std::move(triangles));
    const uint32_t n = static_cast<uint32_t>(pts.size());
    level_.push_back({0, n, 0, n > batch ? points_box(pts, order, 0, n) : BBox{}});
  }

  // Splits every box of the current level, appending the leaves it makes. Returns whether boxes
  // are left for another level.
  bool next_level(std::vector<RegionLeaf>& leaves) {
    std::vector<Node> next;
    for (const Node& nd : level_) split(nd, leaves, next);
    level_ = std::move(next);
    return !level_.empty();
  }

 private:
  struct Node {
    uint32_t begin, end;  // range of `order`
    uint32_t list;        // the parent's touching triangles, in `lists_`
    BBox box;             // the tight box of the range's points
  };

  void split(const Node& nd, std::vector<RegionLeaf>& leaves, std::vector<Node>& next) {
    if (nd.end - nd.begin <= batch_) {
      leaves.push_back({nd.begin, nd.end, false});
      return;
    }
    const BBox& b = nd.box;
    const bool straddles = oracle_box_.valid() && oracle_box_.overlaps(b) && !oracle_box_.contains(b);
    surface_.touching(b, lists_[nd.list], narrowed_);
    if (narrowed_.empty() && !straddles) {
      leaves.push_back({nd.begin, nd.end, true});
      return;
    }
    // Every triangle in the box within `slab` of one plane: the box's points beyond the slab on
    // either side lie in a convex region the surface does not cross (uniform); those in the
    // slab are classified one by one.
    Plane pl;
    if (!straddles && surface_.common_plane(narrowed_, slab_, pl)) {
      auto first = order_.begin() + nd.begin, last = order_.begin() + nd.end;
      const auto below =
          std::partition(first, last, [&](uint32_t i) { return pl.signed_distance(pts_[i]) < -slab_; });
      const auto within =
          std::partition(below, last, [&](uint32_t i) { return pl.signed_distance(pts_[i]) <= slab_; });
      const uint32_t u = static_cast<uint32_t>(below - order_.begin()),
                     w = static_cast<uint32_t>(within - order_.begin());
      if (u > nd.begin) leaves.push_back({nd.begin, u, true});
      if (w > u) leaves.push_back({u, w, false});
      if (nd.end > w) leaves.push_back({w, nd.end, true});
      return;
    }
    const Vec3 ext = b.hi - b.lo;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    auto coord = [axis](const Vec3& v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
    const double mid = 0.5 * (coord(b.lo) + coord(b.hi));
    // The children's tight boxes are gathered by the partition itself, which tests each point
    // exactly once (one pass over the points instead of three).
    BBox halves[2];
    auto grow = [](BBox& h, const Vec3& v) {  // an empty BBox holds ±1e300: min and max start it
      h.lo = {std::min(h.lo.x, v.x), std::min(h.lo.y, v.y), std::min(h.lo.z, v.z)};
      h.hi = {std::max(h.hi.x, v.x), std::max(h.hi.y, v.y), std::max(h.hi.z, v.z)};
    };
    const auto cut = std::partition(order_.begin() + nd.begin, order_.begin() + nd.end, [&](uint32_t i) {
      const bool low = coord(pts_[i]) < mid;
      grow(halves[low ? 0 : 1], pts_[i]);
      return low;
    });
    const uint32_t c = static_cast<uint32_t>(cut - order_.begin());
    if (c == nd.begin || c == nd.end) {  // coincident points: no split separates them
      leaves.push_back({nd.begin, nd.end, false});
      return;
    }
    const uint32_t list = static_cast<uint32_t>(lists_.size());
    lists_.push_back(narrowed_);
    next.push_back({nd.begin, c, list, halves[0]});
    next.push_back({c, nd.end, list, halves[1]});
  }

  const std::vector<Vec3>& pts_;
  const size_t batch_;
  const SurfaceIndex& surface_;
  const double slab_;
  const BBox& oracle_box_;
  std::vector<uint32_t>& order_;
  std::vector<std::vector<uint32_t>> lists_;
  std::vector<Node> level_;
  std::vector<uint32_t> narrowed_;
};

}  // namespace

// Step 2: how many points are inside. Round 1 classifies the representatives of the untouched
// leaves. Representatives that disagree mark a region where the oracle itself is not constant
// (rays escaping through gaps of an open or non-manifold input): its other points are classified
// one by one in round 2, with the points of the touched leaves, as a full vote would. A vote that
// may stop classifies each level's representatives as soon as the level is split, and stops once
// what they settle holds both labels `mixed_at` times: a settled leaf's points and an unsettled
// leaf's representatives count in the end whatever round 2 finds.
RegionCount region_vote(const std::vector<Vec3>& pts, uint64_t first_id, size_t batch,
                        const SurfaceIndex& surface, std::vector<uint32_t> triangles, double slab,
                        const BBox& oracle_box, const PointClassifier& classify, size_t& classified,
                        size_t mixed_at) {
  if (pts.empty()) return {};
  std::vector<uint32_t> order(pts.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  RegionSplit regions(pts, batch, surface, std::move(triangles), slab, oracle_box, order);
  std::vector<RegionLeaf> leaves;
  std::vector<size_t> yes;  // per leaf: its representatives inside
  auto ask = [&](const RegionLeaf& l) { return l.uniform ? std::min<size_t>(batch, l.end - l.begin) : 0; };
  auto settled = [&](size_t li) {
    return leaves[li].uniform && (yes[li] == 0 || yes[li] == ask(leaves[li]));
  };
  std::vector<Vec3> q;
  std::vector<uint64_t> ids;
  auto add = [&](uint32_t from, uint32_t to) {
    for (uint32_t k = from; k < to; ++k) {
      q.push_back(pts[order[k]]);
      ids.push_back(first_id + order[k]);
    }
  };
  RegionCount known{0, 0, false};
  // Round 1 for the leaves found since the last call.
  auto representatives = [&] {
    const size_t from = yes.size();
    q.clear();
    ids.clear();
    for (size_t li = from; li < leaves.size(); ++li)
      add(leaves[li].begin, leaves[li].begin + static_cast<uint32_t>(ask(leaves[li])));
    std::vector<uint8_t> reps;
    if (!q.empty()) classify(q, ids, reps);
    classified += q.size();
    yes.resize(leaves.size(), 0);
    for (size_t li = from, at = 0; li < leaves.size(); ++li) {
      const size_t asked = ask(leaves[li]);
      for (size_t k = 0; k < asked; ++k) yes[li] += reps[at + k] != 0;
      at += asked;
      const size_t m = settled(li) ? leaves[li].end - leaves[li].begin : asked;
      const size_t y = settled(li) ? (yes[li] ? m : 0) : yes[li];
      known.in += y;
      known.out += m - y;
    }
    return mixed_at > 0 && known.in >= mixed_at && known.out >= mixed_at;
  };
  for (bool more = true; more;) {
    more = regions.next_level(leaves);
    if ((mixed_at > 0 || !more) && representatives()) return known;
  }
  // Round 2.
  q.clear();
  ids.clear();
  for (size_t li = 0; li < leaves.size(); ++li)
    if (!settled(li)) add(leaves[li].begin + static_cast<uint32_t>(ask(leaves[li])), leaves[li].end);
  std::vector<uint8_t> rest;
  if (!q.empty()) classify(q, ids, rest);
  classified += q.size();
  size_t in = 0;
  for (size_t li = 0, r = 0; li < leaves.size(); ++li) {
    const size_t m = leaves[li].end - leaves[li].begin;
    if (settled(li)) {
      in += yes[li] ? m : 0;
      continue;
    }
    in += yes[li];
    for (size_t k = ask(leaves[li]); k < m; ++k) in += rest[r++] != 0;
  }
  return {in, pts.size() - in, true};
}

std::vector<Vec3> sample_cell(const CellComplex& cx, uint32_t cell, int count, uint64_t seed) {
  struct Tet {
    Vec3 a, b, c, d;
    double vol;
  };
  std::vector<Tet> tets;
  const auto& facets = cx.cell(cell).facets;
  const Vec3 o = cx.cell_centroid(cell);
  double total = 0;
  for (uint32_t f : facets) {
    const auto loop = cx.outward_loop(f, cell);
    for (size_t i = 1; i + 1 < loop.size(); ++i) {
      Tet t{o, cx.point(loop[0]), cx.point(loop[i]), cx.point(loop[i + 1]), 0};
      t.vol = std::abs(dot(t.b - t.a, cross(t.c - t.a, t.d - t.a))) / 6.0;
      total += t.vol;
      tets.push_back(t);
    }
  }
  std::vector<Vec3> pts;
  if (total <= 0 || count <= 0) return pts;
  pts.reserve(count);
  // R3 low-discrepancy sequence with a seeded offset; counts per tetrahedron by cumulative rounding.
  constexpr double g = 1.22074408460575947536;
  const double a1 = 1 / g, a2 = 1 / (g * g), a3 = 1 / (g * g * g);
  const uint64_t h = splitmix64(seed);
  double o1 = (h & 0xffff) / 65536.0, o2 = ((h >> 16) & 0xffff) / 65536.0,
         o3 = ((h >> 32) & 0xffff) / 65536.0;
  double cum = 0;
  long done = 0;
  size_t k = 0;
  for (const Tet& t : tets) {
    cum += t.vol;
    const long upto = std::lround(count * cum / total);
    for (; done < upto; ++done, ++k) {
      // frac(x) = x - floor(x): exact for x >= 0, the same bits as fmod(x, 1) and far cheaper.
      // For 0 <= x < 2^63 floor(x) is the truncation to an integer (one instruction; std::floor
      // is a library call without SSE4.1).
      const double x1 = o1 + a1 * k, x2 = o2 + a2 * k, x3 = o3 + a3 * k;
      auto frac = [](double x) { return x - static_cast<double>(static_cast<int64_t>(x)); };
      const double s = frac(x1), u = frac(x2), w = frac(x3);
      pts.push_back(fold_to_tet(s, u, w, t.a, t.b, t.c, t.d));
    }
  }
  return pts;
}

namespace {

// A cell's vote: its label and its inconsistent volume (the score that queues it).
struct CellVote {
  bool inside = false;
  double score = 0;
  bool partial = false;  // stopped once inconsistent: label and score are estimates
  float share = 0;       // the inside share r
};

// The carving's constants, derived once from its parameters and the root cell.
struct CarveScale {
  double unit;        // c³
  double hair;        // δ/10 unless set
  double box_volume;  // the root cell's
  BBox outer;         // the root cell's box
};

// A cell's label and inconsistent volume from its inside share `r` (volume `v`, box `box`).
CellVote score_vote(double r, double v, const BBox& box, const CarveParams& p, const CarveScale& k) {
  CellVote out;
  out.share = static_cast<float>(r);
  out.inside = r > p.inside_vote;
  out.score = out.inside ? v * (1 - r) : v * r;
  // An inside cell reaching more than δ out of the oracle's box has air in it for sure (beyond
  // the box everything is outside), however few of its points fell there (a sliver hanging out
  // of an open bottom): it stays in the queue for the open-bottom cap plane.
  if (out.inside && p.oracle_box.valid() && !p.oracle_box.contains(box, p.dist))
    out.score = std::max(out.score, 2 * p.inconsistency * k.unit);
  return out;
}

// A valid solid's cell that the surface only grazes (CarveParams::grazing): the points in the band
// along its facets are voted as in a full vote (same ids, so the same labels), and the first
// `vote_batch` points beyond the band decide all of those by majority. Reentrant (the two
// children of a split are voted at once).
void band_vote(const std::vector<Plane>& outward, const std::vector<Vec3>& pts, uint64_t first_id,
               const CarveParams& p, const PointClassifier& classify, size_t& in, size_t& points) {
  std::vector<Vec3> voted;
  std::vector<uint64_t> ids;
  std::vector<uint8_t> in_batch, flags;
  size_t batch = 0, rest = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    double depth = std::numeric_limits<double>::infinity();
    for (const Plane& pl : outward) depth = std::min(depth, -pl.signed_distance(pts[i]));
    const bool in_band = depth <= p.band;
    if (!in_band && batch == static_cast<size_t>(p.vote_batch)) {
      ++rest;
      continue;
    }
    batch += !in_band;
    voted.push_back(pts[i]);
    ids.push_back(first_id + i);
    in_batch.push_back(!in_band);
  }
  classify(voted, ids, flags);
  size_t batch_in = 0;
  for (size_t k = 0; k < flags.size(); ++k) {
    in += flags[k] != 0;
    batch_in += in_batch[k] && flags[k];
  }
  if (2 * batch_in > batch) in += rest;
  points += voted.size();
}

// A valid solid's touched cell labelled by its exact inside volume (CarveParams::inside_volume,
// docs/design.md "Inside volume by columns"); nothing when that would cost more than its vote.
// The carving resolves what a vote of n points resolves, no finer: a mislabelled share below one
// point's (1/n) counts as none. Finer shares are the input faces' fitting noise along the cell's
// facets; splitting for them multiplies cells, not accuracy.
std::optional<CellVote> measured_vote(const CellComplex& cx, uint32_t c, const BBox& box, double v, long n,
                                      const CarveParams& p, const CarveScale& k) {
  ConvexPolytope poly;
  for (uint32_t f : cx.cell(c).facets) {
    for (uint32_t vid : cx.outward_loop(f, c)) poly.points.push_back(cx.point(vid));
    poly.close_face();
  }
  const double inside = p.inside_volume(poly, box);
  if (inside < 0) return std::nullopt;
  double r = v > 0 ? std::clamp(inside / v, 0.0, 1.0) : 0.0;
  if (std::min(r, 1 - r) * static_cast<double>(n) < 1) r = r > p.inside_vote ? 1.0 : 0.0;
  return score_vote(r, v, box, p, k);
}

// Votes one cell (`box`: its vertices' box). A cell the input surface does not touch is entirely
// inside or outside: a few points (majority) decide it. A valid solid's touched cell is measured
// (measured_vote); else a cell the surface only grazes is voted in a band along its facets; any
// other is voted by regions (parity) or point by point. Reentrant for distinct cells whose volume
// and centroid are measured (CellComplex caches them lazily).
CellVote vote_cell(const CellComplex& cx, uint32_t c, const BBox& box, const CarveParams& p,
                   const CarveScale& k, const PointClassifier& classify, size_t& points, bool may_stop) {
  const double v = cx.cell_volume(c);
  const long n = std::clamp<long>(static_cast<long>(std::ceil(v / k.unit)), p.min_points, p.max_points);
  const bool touched = !p.surface_touches || p.vote_batch <= 0 || p.surface_touches(box);
  if (p.inside_volume && touched)
    if (std::optional<CellVote> measured = measured_vote(cx, c, box, v, n, p, k)) return *measured;
  const uint64_t seed = p.seed ^ (uint64_t(c) << 20);
  const uint64_t first_id = (uint64_t(c) << 24) ^ p.seed;
  const bool free_cell = !touched;
  const auto pts = sample_cell(
      cx, c, free_cell ? std::min<int>(p.vote_batch, static_cast<int>(n)) : static_cast<int>(n), seed);
  size_t in = 0;
  // The cell's outward facet planes and the triangles near it, for the band's and the regions'
  // tests alike (one query of the index). Where both read the triangles entering by a hair, the
  // list is clipped once.
  const bool surface_tests = !free_cell && p.vote_batch > 0 && (p.grazing || p.regions);
  const std::vector<Plane> outward = surface_tests ? outward_planes(cx, c) : std::vector<Plane>{};
  const SurfaceIndex* index = p.grazing ? p.grazing : p.regions;
  const std::vector<uint32_t> near = surface_tests ? index->touching(box) : std::vector<uint32_t>{};
  const bool one_index = p.regions == index;  // the regions' triangles are `near`'s ids
  std::optional<std::vector<uint32_t>> entering;
  if (surface_tests && p.grazing && one_index && p.graze_depth == k.hair)
    entering = p.regions->entering(outward, near, k.hair);
  const bool grazed = surface_tests && p.grazing &&
                      !(entering ? !entering->empty() : p.grazing->enters(outward, near, p.graze_depth));
  if (grazed) band_vote(outward, pts, first_id, p, classify, in, points);
  if (!grazed && !free_cell && p.regions && p.vote_batch > 0) {
    if (!entering)
      entering = p.regions->entering(outward, one_index ? near : p.regions->touching(box), k.hair);
    // The score queues a cell when more than `inconsistency` c³ of it is mislabelled, i.e. when
    // both labels hold more than that volume's share of the n points.
    const size_t mixed_at =
        may_stop && v > 0
            ? static_cast<size_t>(std::floor(p.inconsistency * k.unit * static_cast<double>(n) / v)) + 1
            : 0;
    const RegionCount count =
        region_vote(pts, first_id, static_cast<size_t>(p.vote_batch), *p.regions, std::move(*entering),
                    k.hair, p.oracle_box, classify, points, mixed_at);
    if (!count.complete) {
      // The label and the score (only the queue's order reads it) are estimated with the
      // unsettled points counted half inside: the settled ones alone lie away from the surface
      // and bias the order (docs/design.md). The score still exceeds the inconsistency bound.
      CellVote out = score_vote(
          (double(count.in) + 0.5 * double(pts.size() - count.in - count.out)) / double(pts.size()), v, box,
          p, k);
      out.partial = true;
      return out;
    }
    in = count.in;
  } else if (!grazed) {
    std::vector<uint64_t> ids(pts.size());
    std::vector<uint8_t> flags;
    for (size_t i = 0; i < pts.size(); ++i) ids[i] = first_id + i;
    classify(pts, ids, flags);
    for (uint8_t f : flags) in += f != 0;
    points += pts.size();
    if (free_cell) in = 2 * in > pts.size() ? pts.size() : 0;  // unanimous by construction
  }
  return score_vote(pts.empty() ? 0.0 : double(in) / pts.size(), v, box, p, k);
}

// The plane that cuts a queued cell: the largest remaining region plane that really crosses it.
// Planes passed over only because of a hair-close vertex move to `deferred` (they stay for the
// sub-cells). Returns the index into `remaining`, or nothing.
std::optional<size_t> choose_plane(const CellComplex& cx, uint32_t c, const std::function<double()>& score,
                                   const std::vector<uint32_t>& remaining,
                                   const std::vector<CarvePlane>& planes, const CarveParams& p,
                                   const CarveScale& k, std::vector<uint32_t>& deferred) {
  const CellVertices cv(cx, c);
  for (size_t i = 0; i < remaining.size(); ++i) {
    const Crossing x = crosses(cx, cv, planes[remaining[i]], p.dist, k.hair, k.outer);
    if (x == Crossing::Yes) return i;
    if (x == Crossing::Hair) deferred.push_back(remaining[i]);
  }
  // Only hair-blocked planes are left, yet the cell is inconsistent (it was queued). The hair
  // rule guards the output grid; a plane whose hair-close vertices all keep at least `min_gap`
  // from it cannot make vertices that collapse there, so it still cuts a cell of which at least
  // kHairCutShare is mislabelled (otherwise such a cell can keep metres of air). Only badly
  // mislabelled cells: cutting every such cell makes parts less convex, and gaps below min_gap
  // (fitting noise) break parts when quantised (docs/algorithm.md §7.4, docs/design.md "Valid
  // solids at every step").
  if (p.min_gap <= 0 || score() < kHairCutShare * cx.cell_volume(c)) return std::nullopt;
  auto it = std::find_if(deferred.begin(), deferred.end(), [&](uint32_t q) {
    return hair_gap(cx, cv, planes[q], k.hair, k.outer) >= p.min_gap;
  });
  if (it == deferred.end()) return std::nullopt;
  const size_t i =
      static_cast<size_t>(std::find(remaining.begin(), remaining.end(), *it) - remaining.begin());
  deferred.erase(it);
  return i;
}

// Votes the two children of a split at once, each with its own points (the same ids and labels
// as one after the other; docs/algorithm.md §7.3), after finding the planes of `remaining` that
// still cross each (`kept`). A child without planes left is never split: its vote is complete.
// Returns the oracle's queries.
size_t vote_children(const CellComplex& cx, const uint32_t (&child)[2],
                     const std::vector<uint32_t>& remaining, const std::vector<CarvePlane>& planes,
                     const CarveParams& p, const CarveScale& k, const PointClassifier& classify,
                     std::vector<uint32_t> (&kept)[2], CellVote (&votes)[2]) {
  BBox box[2];
  for (int j = 0; j < 2; ++j) {
    const CellVertices cv_child(cx, child[j]);
    for (uint32_t q : remaining)
      if (crosses(cx, cv_child, planes[q], p.dist, k.hair, k.outer) != Crossing::No) kept[j].push_back(q);
    box[j] = cv_child.box;
    cx.cell_volume(child[j]);  // measured (and cached) before the votes read it
  }
  size_t points[2] = {0, 0};
  auto vote = [&](int j) {
    return with_thread_tag(
        [&, j] { votes[j] = vote_cell(cx, child[j], box[j], p, k, classify, points[j], !kept[j].empty()); });
  };
  tbb::parallel_invoke(vote(0), vote(1));
  return points[0] + points[1];
}

}  // namespace

CarveResult carve(CellComplex& cx, const std::vector<CarvePlane>& planes, const PointClassifier& classify,
                  const CarveParams& p, std::chrono::steady_clock::time_point deadline) {
  CarveResult res;
  const CarveScale k{p.cell_size * p.cell_size * p.cell_size, p.hair_or_default(),
                     cx.cell_volume(cx.root_cell()), cx.cell_bbox(cx.root_cell())};
  std::vector<uint8_t> inside_label(cx.num_cells() + 1024, 0);
  struct Entry {
    double score;
    uint32_t cell;
    bool operator<(const Entry& o) const { return score != o.score ? score < o.score : cell > o.cell; }
  };
  std::priority_queue<Entry> queue;
  std::vector<std::vector<uint32_t>> todo(cx.num_cells());  // remaining plane indices per cell
  auto enqueue = [&](uint32_t c, double score, std::vector<uint32_t> remaining) {
    const bool big_outside = !inside_label[c] && cx.cell_volume(c) > 0.05 * k.box_volume;
    if (remaining.empty() || !(score > p.inconsistency * k.unit || big_outside)) return;
    if (todo.size() <= c) todo.resize(c + 1024);
    todo[c] = std::move(remaining);
    queue.push({score, c});
  };

  std::vector<uint32_t> all(planes.size());
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  const uint32_t root = cx.root_cell();
  const CellVote root_vote = vote_cell(cx, root, k.outer, p, k, classify, res.points, !all.empty());
  inside_label[root] = root_vote.inside;
  // Cells whose vote stopped once they were known to be inconsistent (they are queued, to be
  // split); one that is not split after all is voted in full before its label counts.
  std::vector<uint8_t> partial(inside_label.size(), 0);
  partial[root] = root_vote.partial;
  std::vector<float>& share = res.inside_share;
  share.assign(inside_label.size(), kNoShare);
  share[root] = root_vote.share;
  auto complete_vote = [&](uint32_t c, double& score) {
    if (!partial[c]) return;
    const CellVote full = vote_cell(cx, c, cx.cell_bbox(c), p, k, classify, res.points, false);
    inside_label[c] = full.inside;
    share[c] = full.share;
    partial[c] = 0;
    score = full.score;
  };
  enqueue(root, root_vote.score, all);

  while (!queue.empty()) {
    if (std::chrono::steady_clock::now() > deadline || cx.num_cells() > p.max_cells) {
      res.truncated = true;
      break;
    }
    const uint32_t c = queue.top().cell;
    double score = queue.top().score;
    queue.pop();
    std::vector<uint32_t> remaining = std::move(todo[c]);
    std::vector<uint32_t> deferred;
    auto full_score = [&] {
      complete_vote(c, score);
      return score;
    };
    const std::optional<size_t> i = choose_plane(cx, c, full_score, remaining, planes, p, k, deferred);
    if (!i) {
      complete_vote(c, score);
      continue;
    }
    auto split = cx.split(c, planes[remaining[*i]].plane);
    remaining.erase(remaining.begin(), remaining.begin() + static_cast<long>(*i) + 1);
    remaining.insert(remaining.begin(), deferred.begin(), deferred.end());
    if (!split) {  // cannot happen after `crosses`, but never loop on it
      enqueue(c, 1e300, remaining);
      continue;
    }
    ++res.splits;
    const uint32_t child[2] = {split->neg, split->pos};
    std::vector<uint32_t> kept[2];
    CellVote votes[2];
    res.points += vote_children(cx, child, remaining, planes, p, k, classify, kept, votes);
    if (inside_label.size() <= std::max(child[0], child[1])) {
      inside_label.resize(std::max(child[0], child[1]) + 1024, 0);
      partial.resize(inside_label.size(), 0);
      share.resize(inside_label.size(), kNoShare);
    }
    for (int j = 0; j < 2; ++j) {
      inside_label[child[j]] = votes[j].inside;
      partial[child[j]] = votes[j].partial;
      share[child[j]] = votes[j].share;
      enqueue(child[j], votes[j].score, std::move(kept[j]));
    }
  }
  for (uint32_t c : cx.live_cells()) {
    ++res.cells;
    // A cell left in the queue by a carving cut short keeps its estimated label: completing its
    // vote would be work after the deadline (or beyond max_cells).
    if (c < partial.size()) partial[c] = 0;
    if (c < inside_label.size() && inside_label[c]) res.inside.push_back(c);
  }
  return res;
}

namespace {

// Cell c's inside share: its vote's, or unanimous for its side `in` when it has none.
float share_of(const std::vector<float>& share, uint32_t c, bool in) {
  return c < share.size() && share[c] >= 0 ? share[c] : (in ? 1.0f : 0.0f);
}

// The cost of flipping cell c (remove_pinch_edges): the vote's volume it puts on the wrong side.
double flip_cost(const CellComplex& cx, const std::vector<uint32_t>& inside, const std::vector<float>& share,
                 uint32_t c) {
  const bool in = std::binary_search(inside.begin(), inside.end(), c);
  const double r = share_of(share, c, in);
  return cx.cell_volume(c) * (in ? 2 * r - 1 : 1 - 2 * r);
}

void toggle(std::vector<uint32_t>& cells, uint32_t c) {
  auto it = std::lower_bound(cells.begin(), cells.end(), c);
  if (it != cells.end() && *it == c) cells.erase(it);
  else cells.insert(it, c);
}

// The registry plane nearest the points `at` among the carving planes that really cross cell c
// and leave every one of them on one side (beyond the hair), or nothing.
std::optional<uint32_t> nearest_plane_beside(const CellComplex& cx, uint32_t c, const std::vector<Vec3>& at,
                                             const PinchCuts& cuts, double hair) {
  const CellVertices cv(cx, c);
  std::optional<uint32_t> cut;
  double nearest = std::numeric_limits<double>::infinity();
  for (const CarvePlane& q : *cuts.planes) {
    const Plane& pl = cx.planes()[q.plane];
    bool pos = true, neg = true;
    double d = 0;
    for (const Vec3& a : at) {
      const double s = pl.signed_distance(a);
      pos &= s > hair;
      neg &= s < -hair;
      d = std::max(d, std::abs(s));
    }
    if ((pos || neg) && d < nearest &&
        crosses(cx, cv, q, cuts.params->dist, hair, cuts.outer) == Crossing::Yes) {
      nearest = d;
      cut = q.plane;
    }
  }
  return cut;
}

// Splits cell c by `plane`; both pieces keep its label and share (`inside` stays sorted).
// Returns whether it split.
bool split_keeping_label(CellComplex& cx, uint32_t c, uint32_t plane, std::vector<uint32_t>& inside,
                         std::vector<float>& share) {
  const bool was_inside = std::binary_search(inside.begin(), inside.end(), c);
  const float r = share_of(share, c, was_inside);
  const auto split = cx.split(c, plane);
  if (!split) return false;
  const uint32_t kids[2] = {split->neg, split->pos};
  if (share.size() <= std::max(kids[0], kids[1])) share.resize(std::max(kids[0], kids[1]) + 1, kNoShare);
  if (was_inside) toggle(inside, c);
  for (uint32_t kid : kids) {
    share[kid] = r;
    if (was_inside) toggle(inside, kid);
  }
  return true;
}

// The first pinch that can still be repaired: the cells around it that have not flipped yet
// (sorted, distinct) and its vertices (an edge's two or one vertex); nothing when none is left.
// Pinch edges first, then pinched vertices.
std::pair<std::vector<uint32_t>, std::vector<uint32_t>> first_pinch(
    const CellComplex& cx, const std::map<uint64_t, std::vector<std::pair<uint32_t, uint32_t>>>& uses,
    const std::vector<uint32_t>& vertices, const std::unordered_set<uint32_t>& flipped) {
  std::vector<uint32_t> around, where;
  auto gather = [&](const std::vector<std::pair<uint32_t, uint32_t>>& inc) {
    for (const auto& [f, c] : inc)
      for (uint32_t x : {c, cx.other_side(f, c)})
        if (x != CellComplex::kNone && !flipped.count(x)) around.push_back(x);
  };
  for (const auto& [e, inc] : uses) {
    if (inc.size() <= 2) continue;
    gather(inc);
    if (!around.empty()) {
      where = {uint32_t(e >> 32), uint32_t(e & 0xffffffffu)};
      break;
    }
  }
  // The cells on either side of the boundary facets around a pinched vertex.
  for (size_t i = 0; around.empty() && i < vertices.size(); ++i) {
    const uint32_t v = vertices[i];
    for (const auto& [e, inc] : uses)
      if (uint32_t(e >> 32) == v || uint32_t(e & 0xffffffffu) == v) gather(inc);
    if (!around.empty()) where = {v};
  }
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  return {around, where};
}

size_t repair_pinches(const CellComplex& cx, CellComplex* cutting, std::vector<uint32_t>& inside,
                      double& flipped_volume, std::vector<float>& share, const PinchCuts* cuts) {
  auto pinch_count = [&](const std::vector<uint32_t>& cells) {
    const auto uses = boundary_edge_uses(cx, cells);  // edge -> (facet, inner cell)
    size_t n = 0;
    for (const auto& [e, inc] : uses)
      if (inc.size() > 2) ++n;
    auto vertices = pinch_vertices(uses, [](const auto& fc) { return fc.first; });
    n += vertices.size();
    return std::make_tuple(n, uses, std::move(vertices));
  };
  auto cost = [&](uint32_t c) { return flip_cost(cx, inside, share, c); };
  const double hair = cuts ? cuts->params->hair_or_default() : 0;
  // Each cell changes side at most once, so the repair cannot oscillate (a flip that removes one
  // pinch may create another next to it); among the cells around a pinch the one whose flip puts
  // the least of the vote's volume on the wrong side and lowers the number of pinches is taken,
  // else the first in that order (docs/algorithm.md §8). Flipping a cell of volume V and inside
  // share r from inside to outside costs (2r − 1)·V, from outside to inside (1 − 2r)·V; a cell
  // without a share counts as unanimous (its whole volume). When that flip would cost more than
  // `cuts->max_flip`, the cheapest such cell that a carving plane beside the pinch crosses is cut
  // by the nearest one (the pinch stays on one side), and the pinch is looked at again.
  constexpr int kMaxCuts = 8;                    // per pinch
  constexpr size_t kMaxAllCuts = 256;            // per repair: each cut is a split of the complex
  auto lowers = [&](uint32_t c, size_t count) {  // whether flipping c lowers the pinch count
    std::vector<uint32_t> trial = inside;
    toggle(trial, c);
    return std::get<0>(pinch_count(trial)) < count;
  };
  // Cuts the first cell of `order` from `first` on whose flip lowers the count and that a plane
  // beside the pinch crosses. False if none.
  auto cut_down = [&](const std::vector<std::pair<double, uint32_t>>& order, size_t first,
                      const std::vector<uint32_t>& where, size_t count) {
    std::vector<Vec3> at;
    for (uint32_t v : where) at.push_back(cx.point(v));
    for (size_t k = first; k < order.size(); ++k) {
      const uint32_t c = order[k].second;
      if (k > first && !lowers(c, count)) continue;
      if (const auto plane = nearest_plane_beside(cx, c, at, *cuts, hair);
          plane && split_keeping_label(*cutting, c, *plane, inside, share))
        return true;
    }
    return false;
  };
  std::unordered_set<uint32_t> flipped;
  std::map<std::vector<uint32_t>, int> cut_at;  // pinch (its vertices) -> cuts made there
  size_t all_cuts = 0;
  size_t flips = 0;
  std::sort(inside.begin(), inside.end());
  for (;;) {
    auto [count, uses, vertices] = pinch_count(inside);
    if (count == 0) return flips;
    const auto [around, where] = first_pinch(cx, uses, vertices, flipped);
    if (around.empty()) return flips;  // every cell around every pinch has flipped once: give up
    std::vector<std::pair<double, uint32_t>> order;
    for (uint32_t c : around) order.emplace_back(cost(c), c);
    std::sort(order.begin(), order.end(), [&](const auto& a, const auto& b) {
      if (a.first != b.first) return a.first < b.first;
      const double va = cx.cell_volume(a.second), vb = cx.cell_volume(b.second);
      return va != vb ? va < vb : a.second < b.second;
    });
    size_t first = 0;  // the cheapest flip that lowers the count
    while (first < order.size() && !lowers(order[first].second, count)) ++first;
    const uint32_t pick = first < order.size() ? order[first].second : order.front().second;
    if (cutting && first < order.size() && cost(pick) > cuts->max_flip && cut_at[where] < kMaxCuts &&
        all_cuts < kMaxAllCuts && cut_down(order, first, where, count)) {
      ++cut_at[where];
      ++all_cuts;
      continue;
    }
    toggle(inside, pick);
    flipped.insert(pick);
    flipped_volume += cx.cell_volume(pick);
    ++flips;
  }
}

}  // namespace

size_t remove_pinch_edges(const CellComplex& cx, std::vector<uint32_t>& inside, double& flipped_volume,
                          const std::vector<float>& share) {
  std::vector<float> shares = share;
  return repair_pinches(cx, nullptr, inside, flipped_volume, shares, nullptr);
}

size_t remove_pinch_edges(CellComplex& cx, std::vector<uint32_t>& inside, double& flipped_volume,
                          std::vector<float>& share, const PinchCuts& cuts) {
  return repair_pinches(cx, &cx, inside, flipped_volume, share, &cuts);
}

size_t flip_thin_cells(const CellComplex& cx, std::vector<uint32_t>& inside, double width,
                       double& flipped_volume) {
  std::unordered_set<uint32_t> in(inside.begin(), inside.end());
  auto depth = [&](uint32_t c) {
    const std::vector<uint32_t> vs = cx.cell_vertices(c);
    double d = std::numeric_limits<double>::infinity();
    for (uint32_t f : cx.cell(c).facets) {
      const Vec3 n = cx.outward_normal(f, c);
      const Vec3& p = cx.point(cx.facet(f).loop[0]);
      double deepest = 0;
      for (uint32_t v : vs) deepest = std::max(deepest, dot(n, p - cx.point(v)));
      d = std::min(d, deepest);
    }
    return d;
  };
  std::vector<uint32_t> flip;
  for (uint32_t c : cx.live_cells()) {
    const bool is_in = in.count(c) > 0;
    bool boundary = false, open = false;
    for (uint32_t f : cx.cell(c).facets) {
      const uint32_t o = cx.other_side(f, c);
      if (o == CellComplex::kNone) open = true;
      else if ((in.count(o) > 0) != is_in) boundary = true;
    }
    if (boundary && (is_in || !open) && depth(c) < width) flip.push_back(c);
  }
  for (uint32_t c : flip) {
    if (in.count(c)) in.erase(c);
    else in.insert(c);
    flipped_volume += cx.cell_volume(c);
  }
  inside.assign(in.begin(), in.end());
  std::sort(inside.begin(), inside.end());
  return flip.size();
}

size_t fill_cavities(const CellComplex& cx, std::vector<uint32_t>& inside, double& filled_volume) {
  std::unordered_set<uint32_t> in(inside.begin(), inside.end());
  std::unordered_set<uint32_t> reached;
  std::vector<uint32_t> stack;
  const std::vector<uint32_t> live = cx.live_cells();
  for (uint32_t c : live) {
    if (in.count(c)) continue;
    for (uint32_t f : cx.cell(c).facets)
      if (cx.other_side(f, c) == CellComplex::kNone) {
        if (reached.insert(c).second) stack.push_back(c);
        break;
      }
  }
  while (!stack.empty()) {
    const uint32_t c = stack.back();
    stack.pop_back();
    for (uint32_t f : cx.cell(c).facets) {
      const uint32_t o = cx.other_side(f, c);
      if (o != CellComplex::kNone && !in.count(o) && reached.insert(o).second) stack.push_back(o);
    }
  }
  size_t filled = 0;
  for (uint32_t c : live)
    if (!in.count(c) && !reached.count(c)) {
      inside.push_back(c);
      filled_volume += cx.cell_volume(c);
      ++filled;
    }
  std::sort(inside.begin(), inside.end());
  return filled;
}

std::vector<std::vector<uint32_t>> connected_components(const CellComplex& cx,
                                                        const std::vector<uint32_t>& cells) {
  std::unordered_set<uint32_t> in(cells.begin(), cells.end());
  std::unordered_set<uint32_t> seen;
  std::vector<uint32_t> sorted = cells;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<uint32_t>> comps;
  for (uint32_t s : sorted) {
    if (seen.count(s)) continue;
    std::vector<uint32_t> comp, stack{s};
    seen.insert(s);
    while (!stack.empty()) {
      const uint32_t c = stack.back();
      stack.pop_back();
      comp.push_back(c);
      for (uint32_t f : cx.cell(c).facets) {
        const uint32_t o = cx.other_side(f, c);
        if (o != CellComplex::kNone && in.count(o) && seen.insert(o).second) stack.push_back(o);
      }
    }
    std::sort(comp.begin(), comp.end());
    comps.push_back(std::move(comp));
  }
  return comps;
}

}  // namespace mc
