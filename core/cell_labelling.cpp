#include "core/cell_labelling.hpp"

#include <algorithm>
#include <iterator>
#include <cmath>
#include <stdexcept>

#include "core/soup.hpp"
#include "core/surface.hpp"

namespace mc {

namespace {
// The largest share of the cell's volume a pinch repair may flip before cutting the cell down.
constexpr double kMaxPinchFlipShare = 0.01;
// The volume agreement open models are held to (docs/algorithm.md §6.5; the open variants' 2 %).
constexpr double kOpenRelabel = 0.02;
// The most triangles a cell's exact inside volume sums over (about four plane clips each); a
// larger cell under a larger roof is voted, which costs less there (docs/design.md "Inside volume
// by columns").
constexpr size_t kMaxColumns = 256;
}  // namespace

struct CellLabeller::Oracles {
  TriangleSoup tris;         // the cleaned mesh's triangles (surface index)
  const TriangleSoup* soup;  // what the oracles see: the oracle's weld, or `tris`
  std::unique_ptr<InsideOracle> parity;
  std::unique_ptr<VerticalOracle> vertical_input, all_surfaces, vertical_floors;
  std::unique_ptr<SurfaceIndex> index;
  std::unique_ptr<ColumnVolume> columns;  // a valid solid's exact inside volumes
  CarveParams carve;
  const VerticalOracle& vertical() const { return vertical_floors ? *vertical_floors : *vertical_input; }
};

CellLabeller::CellLabeller(const InputFrame& in, const TriangleSoup& oracle_tris, const CarvingPlanes& planes,
                           const PreprocessParams& p, FastPathCheck& fast, Preprocessed& out)
    : planes_(planes), p_(p), out_(out), o_(std::make_unique<Oracles>()) {
  Oracles& o = *o_;
  o.tris = triangulate(in.mesh);
  if (o.tris.triangles.empty()) throw std::runtime_error("degenerate geometry: nothing to triangulate");
  const bool own = oracle_tris.triangles.empty();
  o.soup = own ? &o.tris : &oracle_tris;
  const PolygonMesh& omesh = own ? in.mesh : in.oracle_mesh;
  o.parity = std::make_unique<InsideOracle>(*o.soup, p.oracle_rays, p.seed);
  fast.decide(out);
  o.parity->set_valid_solid(out.fast_path);
  if (out.fast_path && p.column_volumes) o.columns = std::make_unique<ColumnVolume>(*o.soup);
  o.parity->set_merge_distance(out.dist);
  o.parity->set_enclosure(p.fill_enclosed);
  const std::vector<uint8_t> cover = cover_triangles(*o.soup, omesh);
  o.vertical_input = std::make_unique<VerticalOracle>(*o.soup, cover, out.dist, planes.ground_z);
  // Floors of parts whose ground is missing above the lowest level count as ground faces of the
  // vertical vote (docs/algorithm.md §6.4).
  const bool horizontal_holes =
      std::any_of(planes.holes.begin(), planes.holes.end(), [&](const HolePlane& h) {
        return h.loop.size() >= 3 && std::abs(h.plane.n.z) >= std::cos(out.angle_rad);
      });
  if (horizontal_holes)  // every triangle, walls too: what lies below a hole
    o.all_surfaces = std::make_unique<VerticalOracle>(
        *o.soup, std::vector<uint8_t>(o.soup->triangles.size(), 1), out.dist, planes.ground_z);
  if (const TriangleSoup floors = horizontal_holes ? open_bottoms(planes.holes, *o.vertical_input,
                                                                  *o.all_surfaces, out.dist, out.angle_rad)
                                                   : TriangleSoup{};
      !floors.triangles.empty()) {
    TriangleSoup with = *o.soup;
    std::vector<uint8_t> with_cover = cover;
    with_cover.resize(with.triangles.size(), 0);
    const uint32_t base = static_cast<uint32_t>(with.vertices.size());
    with.vertices.insert(with.vertices.end(), floors.vertices.begin(), floors.vertices.end());
    for (const auto& t : floors.triangles) {
      with.triangles.push_back({base + t[0], base + t[1], base + t[2]});
      with.source_face.push_back(UINT32_MAX);
      with_cover.push_back(1);
    }
    o.vertical_floors = std::make_unique<VerticalOracle>(with, with_cover, out.dist, planes.ground_z);
    out.open_bottom_triangles = floors.triangles.size();
  }
  CarveParams& cp = o.carve;
  cp.cell_size = out.cell_size;
  cp.dist = out.dist;
  cp.min_points = p.min_points;
  cp.max_points = p.max_points;
  cp.inside_vote = p.inside_vote;
  cp.inconsistency = p.inconsistency;
  cp.seed = p.seed;
  cp.vote_batch = p.vote_batch;
  cp.min_gap = p.min_gap > 0 ? std::max(p.min_gap, 2 * p.output_grid) : 0.0;
  cp.hair = out.hair;
  o.index = std::make_unique<SurfaceIndex>(o.tris);
}

CellLabeller::~CellLabeller() = default;

const TriangleSoup& CellLabeller::oracle_soup() const { return *o_->soup; }
const TriangleSoup& CellLabeller::surface_triangles() const { return o_->tris; }
const VerticalOracle& CellLabeller::vertical() const { return o_->vertical(); }

Labelling CellLabeller::label(bool use_vertical, Clock::time_point deadline) const {
  const Oracles& o = *o_;
  const VerticalOracle& vertical = o.vertical();
  const SurfaceIndex& index = *o.index;
  Labelling l;
  l.complex = std::make_unique<CellComplex>(*out_.planes, planes_.box);
  CarveParams c = o.carve;
  c.oracle_box = use_vertical ? vertical.bbox() : o.parity->bbox();
  // A cell the surface does not touch is uniformly inside or outside, except across the
  // oracle's box: beyond it everything is outside, so a cell hanging out of an open bottom (no
  // floor face to touch) is not uniform and needs the full vote.
  const BBox ob = c.oracle_box;
  c.surface_touches = [&index, ob](const BBox& b) {
    return index.touches(b) || (ob.overlaps(b) && !ob.contains(b));
  };
  // Parity is constant where the surface does not pass, so a touched cell is voted by regions.
  // The vertical vote is not: under an eave without a wall it changes where no surface is.
  if (!use_vertical && p_.region_votes) c.regions = &index;
  // A valid solid's cell that the surface reaches at most a hair into (fitting noise of the
  // faces along its facets) is uniform but for that band (docs/algorithm.md §7.3).
  if (out_.fast_path && !use_vertical && p_.grazed_cells) {
    c.grazing = &index;
    c.graze_depth = 0.1 * out_.dist;
    c.band = out_.dist;
  }
  // A valid solid's touched cells are labelled by their exact inside volume (docs/design.md
  // "Inside volume by columns"): no sample point near the surface, no seed.
  if (o.columns && !use_vertical) {
    const ColumnVolume& columns = *o.columns;
    c.inside_volume = [&columns](const ConvexPolytope& cell, const BBox& b) {
      return columns.inside(cell, b, kMaxColumns);
    };
  }
  const InsideOracle& parity = *o.parity;
  l.carve = carve(
      *l.complex, planes_.planes,
      [&](const std::vector<Vec3>& pts, const std::vector<uint64_t>& ids, std::vector<uint8_t>& flags) {
        if (use_vertical) vertical.classify(pts, flags);
        else parity.classify(pts, ids, flags);
      },
      c, deadline);
  l.inside = l.carve.inside;
  if (l.inside.empty()) return l;
  // Slabs and wedges thinner than two steps of the output grid cannot be written valid (§8).
  if (p_.output_grid > 0) {
    double thin = 0;
    if (const size_t n = flip_thin_cells(*l.complex, l.inside, 2 * p_.output_grid, thin))
      l.problems.push_back("changed the side of " + std::to_string(n) +
                           " cell(s) thinner than two steps of the output grid (volume " +
                           std::to_string(thin) + ")");
  }
  // A void enclosed by the building would be an inner shell of the cell and of a part: filled.
  double filled = 0;
  size_t cavities = fill_cavities(*l.complex, l.inside, filled);
  // The cells those repairs moved count as unanimous for their new side in the pinch repair's
  // costs (their vote's share would make flipping them back look cheap, and bring back the slab
  // or the cavity).
  {
    std::vector<uint32_t> before = l.carve.inside, now = l.inside, moved;
    std::sort(before.begin(), before.end());
    std::sort(now.begin(), now.end());
    std::set_symmetric_difference(before.begin(), before.end(), now.begin(), now.end(),
                                  std::back_inserter(moved));
    for (uint32_t c : moved)
      if (c < l.carve.inside_share.size()) l.carve.inside_share[c] = kNoShare;
  }
  // A pinch whose cheapest flip would change the cell by more than 1 % of its volume (and more
  // than one vote point's, c³) is cut down first (§8): a wing, or a room of air.
  PinchCuts cuts;
  cuts.planes = &planes_.planes;
  cuts.params = &o.carve;
  cuts.outer = planes_.box;
  cuts.max_flip = std::max(out_.cell_size * out_.cell_size * out_.cell_size,
                           kMaxPinchFlipShare * surface_volume(*l.complex, l.inside));
  double flipped = 0;
  if (const size_t n = remove_pinch_edges(*l.complex, l.inside, flipped, l.carve.inside_share, cuts))
    l.problems.push_back("changed the side of " + std::to_string(n) + " cell(s) at pinch edges (volume " +
                         std::to_string(flipped) + ") to make the singleton cell 2-manifold");
  cavities += fill_cavities(*l.complex, l.inside, filled);
  if (cavities)
    l.problems.push_back("filled " + std::to_string(cavities) + " enclosed outside cell(s) (volume " +
                         std::to_string(filled) + ") so that the singleton cell has no cavity");
  std::sort(l.inside.begin(), l.inside.end());
  if (!l.inside.empty()) l.volume = surface_volume(*l.complex, l.inside);
  return l;
}

Labelling label_with_volume_check(const CellLabeller& labeller, const CarvingPlanes& planes,
                                  const PreprocessParams& p, Clock::time_point deadline, Preprocessed& out) {
  const VerticalOracle& vertical = labeller.vertical();
  // The independent estimate (§6.5): the input's own volume when it is closed and consistently
  // oriented; for an open input the vertical vote integrated over columns. A closed input without
  // a consistent orientation has none: vertical columns merge crossings within δ and miscount
  // thin slabs (sample20: 881,404 m³ against the paper's 937,784 and parity's 938,034).
  VolumeCheck& vc = out.volume_check;
  if (const double v = closed_volume(labeller.oracle_soup()); v > 0 && !out.open_input) {
    vc.estimate = v;
    vc.method = "signed volume";
  } else if (vertical.valid() && planes.vertical_applicable && (out.open_input || planes.want_vertical)) {
    vc.estimate = vertical.volume();
    vc.method = "vertical columns";
  }
  const bool first_vertical = planes.want_vertical && vertical.valid();
  Labelling chosen = labeller.label(first_vertical, deadline);
  vc.oracle = first_vertical ? "vertical" : "parity";
  auto off = [&](double v) { return vc.estimate > 0 ? std::abs(v / vc.estimate - 1) : 0.0; };
  // An open input's cell is investigated sooner than it is reported: its first labelling is the
  // vertical vote, the same vote the estimate integrates, so a cell more than kOpenRelabel off it
  // lost or gained volume in the carving (a missing wall's plane kept out of some cells), and the
  // parity labelling of the same planes may do better; the closer one is kept (§6.5).
  const double investigate = out.open_input ? std::min(p.volume_check, kOpenRelabel) : p.volume_check;
  const bool disagrees = p.volume_check > 0 && vc.estimate > 0 && off(chosen.volume) > investigate;
  // The second labelling uses the other oracle. The parity vote may always replace the vertical
  // one (the estimate is then independent of it). The vertical vote replaces parity only where it
  // is applicable and the estimate does not come from the vertical vote itself: the input is open,
  // its estimate is its signed volume, or parity found no interior at all. Otherwise a closed
  // input keeps its parity cell, and a disagreement is only reported.
  const bool other_possible =
      first_vertical || (vertical.valid() && planes.vertical_applicable &&
                         (out.open_input || vc.method == "signed volume" || chosen.inside.empty()));
  if ((chosen.inside.empty() || disagrees) && other_possible && Clock::now() < deadline) {
    vc.relabelled = true;
    Labelling second = labeller.label(!first_vertical, deadline);
    const bool better =
        !second.inside.empty() && (chosen.inside.empty() || off(second.volume) < off(chosen.volume));
    if (better) {
      chosen = std::move(second);
      vc.oracle = first_vertical ? "parity" : "vertical";
    }
  }
  return chosen;
}

}  // namespace mc
