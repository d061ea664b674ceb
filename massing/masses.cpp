#include "massing/masses.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

#include "core/hull.hpp"
#include "core/union_find.hpp"
#include "massing/plan_geometry.hpp"

namespace mc::massing {

namespace {

double height(const PartMassing& pm) { return pm.z_max - pm.z_min; }

// A part is flat-topped when horizontal upward faces cover this share of its footprint.
constexpr double kFlatTop = 0.9;

// The neighbour a part rests on: its stacked or inclined contact with the largest area, this part
// above; nullptr when there is none.
const Contact* resting_on(const PartMassing& pm) {
  const Contact* below = nullptr;
  for (const Contact& c : pm.contacts)
    if (c.above == 1 && (!below || c.area > below->area)) below = &c;
  return below;
}

// Step 2's test: a raised part with few walls of its own, resting on another part, that is a
// wedge or a slab (it fills at most roof_max_fill of its footprint x height, or is thinner than
// thin_width).
bool roof_piece(const PartMassing& pm, const std::vector<PartMassing>& P, const MassingParams& p) {
  const Contact* below = resting_on(pm);
  if (pm.grounded || !below) return false;
  const double h = height(pm);
  if (!(h > 0) || !(pm.footprint_area > 0)) return false;
  const bool wedge = pm.volume <= p.roof_max_fill * pm.footprint_area * h || h < p.thin_width;
  const bool covers = pm.footprint_area >= p.roof_min_cover * P[below->other].footprint_area;
  return wedge && (pm.wall_share < p.roof_max_wall_share || covers);
}

// The members' vertices, for the hull of a mass.
std::vector<Vec3> vertices_of(const std::vector<uint32_t>& members, const std::vector<PolygonMesh>& meshes) {
  std::vector<Vec3> v;
  for (uint32_t i : members) v.insert(v.end(), meshes[i].vertices.begin(), meshes[i].vertices.end());
  return v;
}

// A façade zone: a strip under twice thin_width wide, at least three times as long, lining a larger
// part from its base (bottoms within mass_height_tolerance) along its long side (a vertical face
// shared over half its length x height) up to more than half that part's height: a gallery, a zone
// of bays, a façade layer thicker than a skin. A low strip along a wall (a lean-to) is an annex when
// it stands on the ground; raised, beside an upper storey on the same floor (a terrace edge, the
// foot of a mansard), it is that storey's at any height, since a raised mass of its own would be a
// rooftop unit (docs/massing.md, "Masses"). A strip standing on a lower part beside the wall is a
// storey of what it stands on.
bool facade_zone(const PartMassing& pm, const std::vector<PartMassing>& P, const MassingParams& p) {
  if (!(pm.width < 2 * p.thin_width) || pm.length < 3 * pm.width) return false;
  for (const Contact& c : pm.contacts) {
    const PartMassing& o = P[c.other];
    if (c.kind == "side" && c.area >= 0.5 * pm.length * height(pm) &&
        o.footprint_area >= 2 * pm.footprint_area &&
        std::abs(pm.z_min - o.z_min) <= p.mass_height_tolerance &&
        (pm.z_max > (o.z_min + o.z_max) / 2 || !pm.grounded))
      return true;
  }
  return false;
}

// The parts of each mass grown so far, by root (empty for a non-root).
std::vector<std::vector<uint32_t>> members_by_root(UnionFind& uf, uint32_t n) {
  std::vector<std::vector<uint32_t>> members(n);
  for (uint32_t i = 0; i < n; ++i) members[uf.find(i)].push_back(i);
  return members;
}

// Joins masses a and b (roots) and their member lists.
void join_masses(uint32_t a, uint32_t b, UnionFind& uf, std::vector<std::vector<uint32_t>>& members) {
  uf.link(a, b);
  const uint32_t r = uf.find(a), other = r == a ? b : a;
  members[r].insert(members[r].end(), members[other].begin(), members[other].end());
  members[other].clear();
}

// Step 1: what kind of piece each part is.
void classify_pieces(std::vector<PartMassing>& P, const MassingParams& p) {
  const size_t n = P.size();
  for (auto& pm : P) {
    pm.piece = "body";
    if (n > 1 && !pm.contacts.empty() && (pm.width < p.thin_width || facade_zone(pm, P, p)))
      pm.piece = "layer";
    else if (roof_piece(pm, P, p)) pm.piece = "roof";
  }
}

// Two roof faces lie in one plane: normals within 2.6° and the one's vertex within 5 cm of the
// other's plane. Pieces the decomposition cut out of one roof share its fitted plane exactly, up
// to the output grid, so these only absorb rounding.
bool coplanar(const RoofFace& f, const RoofFace& g) {
  return dot(f.normal, g.normal) >= 0.999 && std::abs(dot(g.normal, f.point - g.point)) <= 0.05;
}

// Step 2 (d): a slice of a body, cut off under its slope. A lower body standing beside a higher one
// on the same base, at least slice_min_height_share of its height and at most slice_max_width_share
// of its width, whose footprint is covered (slice_roof_share) by sloped roof faces in the planes of
// the higher one's roof faces, nothing standing on it: the strip of a gable's side, the corner
// under a hipped roof. An annex under a catslide roof continues the roof too but is much lower;
// an arm of an L is as wide as the house.
bool slice_of(const std::vector<uint32_t>& low, const std::vector<uint32_t>& high,
              const PartMassing& low_part, const PartMassing& high_part, double low_height,
              double high_height, const std::vector<PartMassing>& P, const MassingParams& p) {
  if (low_height < p.slice_min_height_share * high_height) return false;
  if (low_part.width > p.slice_max_width_share * high_part.width) return false;
  auto in_high_roof = [&](const RoofFace& f) {
    return std::any_of(high.begin(), high.end(), [&](uint32_t j) {
      return std::any_of(P[j].sloped_roof.begin(), P[j].sloped_roof.end(),
                         [&](const RoofFace& g) { return coplanar(f, g); });
    });
  };
  double covered = 0, footprint = 0;  // in plan
  for (uint32_t i : low) {
    footprint += P[i].footprint_area;
    for (const RoofFace& f : P[i].sloped_roof)
      if (in_high_roof(f)) covered += f.area * f.normal.z;
  }
  return footprint > 0 && covered >= p.slice_roof_share * footprint;
}

// Step 2: bodies of one volume, pairs by decreasing shared vertical area, tops within the
// tolerance and (a) bottoms apart: a piece standing on something lower, flush with the top of the
// body beside it (an overhang, an upper storey over an annex); or bottoms within the tolerance too
// and (b) one flat roof, every piece flat-topped, or (c) together about as convex as one part; or
// tops apart, bottoms within the tolerance and (d) the lower is a slice of the higher (slice_of).
// With `through_layers` (step 5), the masses grown so far are joined by the same tests, their
// layers counting as contacts: two blocks of one height with a façade zone between them.
void join_bodies(const std::vector<PartMassing>& P, const std::vector<PolygonMesh>& meshes,
                 const MassingParams& p, UnionFind& uf, bool through_layers) {
  const uint32_t n = static_cast<uint32_t>(P.size());
  std::vector<std::vector<uint32_t>> members = members_by_root(uf, n);
  auto joins = [&](const PartMassing& a) {
    return a.piece == "body" || (through_layers && a.piece == "layer");
  };
  std::vector<std::tuple<double, uint32_t, uint32_t>> pairs;
  for (uint32_t i = 0; i < n; ++i)
    for (const Contact& c : P[i].contacts)
      if (c.other > i && c.kind == "side" && joins(P[i]) && joins(P[c.other]) &&
          c.area >= p.mass_shared_fraction * std::min(height(P[i]), height(P[c.other])) *
                        std::min(P[i].width, P[c.other].width))
        pairs.emplace_back(-c.area, i, c.other);
  std::sort(pairs.begin(), pairs.end());
  auto z_range = [&](const std::vector<uint32_t>& m) {  // of the mass's shape: its layers are skins
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (uint32_t k : m)
      if (P[k].piece != "layer") lo = std::min(lo, P[k].z_min), hi = std::max(hi, P[k].z_max);
    return std::pair{lo, hi};
  };
  auto one_volume = [&](const std::vector<uint32_t>& joint, bool same_top, bool same_bottom) {
    if (!same_top) return false;
    if (!same_bottom) return true;  // (a) a piece flush with the top of a taller one beside it
    if (std::all_of(joint.begin(), joint.end(), [&](uint32_t k) { return P[k].flat_top >= kFlatTop; }))
      return true;      // (b) one flat roof
    double volume = 0;  // (c) one height and about as convex as one part
    for (uint32_t k : joint) volume += P[k].volume;
    const double hull = convex_hull(vertices_of(joint, meshes)).volume;
    return hull > 0 && volume / hull >= p.mass_convexity;
  };
  for (const auto& [neg_area, i, j] : pairs) {
    const uint32_t a = uf.find(i), b = uf.find(j);
    if (a == b) continue;
    const auto [alo, ahi] = z_range(members[a]);
    const auto [blo, bhi] = z_range(members[b]);
    std::vector<uint32_t> joint = members[a];
    joint.insert(joint.end(), members[b].begin(), members[b].end());
    // Tops: a step that is small for the height (0.8 m on a 19 m block) is no new mass.
    const double top_tol =
        std::max(p.mass_height_tolerance, p.mass_height_share * std::min(ahi - alo, bhi - blo));
    const bool same_top = std::abs(ahi - bhi) <= top_tol;
    const bool same_bottom = std::abs(alo - blo) <= p.mass_height_tolerance;
    const bool slice = !same_top && same_bottom &&
                       (ahi < bhi ? slice_of(members[a], members[b], P[i], P[j], ahi - alo, bhi - blo, P, p)
                                  : slice_of(members[b], members[a], P[j], P[i], bhi - blo, ahi - alo, P, p));
    if (!slice && !one_volume(joint, same_top, same_bottom)) continue;
    join_masses(a, b, uf, members);
  }
}

// Step 3: roof pieces join the mass they rest on (lowest first, so a piece on a piece follows it
// down). Step 4: layers join the non-layer neighbour they share most wall with (side contacts
// first, then any contact, then a layer).
void attach_roofs_and_layers(const std::vector<PartMassing>& P, UnionFind& uf) {
  const uint32_t n = static_cast<uint32_t>(P.size());
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return P[a].z_min < P[b].z_min; });
  for (uint32_t i : order)
    if (P[i].piece == "roof") uf.link(uf.find(resting_on(P[i])->other), uf.find(i));
  for (uint32_t i = 0; i < n; ++i) {
    if (P[i].piece != "layer") continue;
    const Contact* best = nullptr;  // side contacts first: a layer leans on a wall, it stands on a roof
    for (int pass = 0; pass < 4 && !best; ++pass)
      for (const Contact& c : P[i].contacts)
        if ((pass % 2 || P[c.other].piece != "layer") && (pass >= 2 || c.kind == "side") &&
            (!best || c.area > best->area))
          best = &c;
    if (best) uf.link(uf.find(best->other), uf.find(i));
  }
}

// Step 6: storeys of one volume. A mass whose top is covered by one mass standing on it (the
// stacked contacts between them sum to storey_min_cover of the lower mass's footprint) is the lower
// storey of that mass, not a base under a setback: a block cut horizontally at a floor, an upper
// floor overhanging the one below. Masses of the highest bodies first, so a stack of storeys joins
// from the top down.
void join_storeys(const std::vector<PartMassing>& P, const MassingParams& p, UnionFind& uf) {
  const uint32_t n = static_cast<uint32_t>(P.size());
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return P[a].z_min > P[b].z_min; });
  std::vector<std::vector<uint32_t>> members = members_by_root(uf, n);
  for (uint32_t i : order) {
    if (P[i].piece != "body") continue;
    const uint32_t low = uf.find(i);
    double footprint = 0;              // the lower mass's plan: its parts less their stacking
    std::map<uint32_t, double> cover;  // mass root -> its area standing on the lower mass
    for (uint32_t k : members[low]) {
      footprint += P[k].footprint_area;
      for (const Contact& c : P[k].contacts)
        if (c.kind == "stacked" && c.above == -1) {
          const uint32_t up = uf.find(c.other);
          if (up == low) footprint -= c.area;
          else cover[up] += c.area;
        }
    }
    for (const auto& [up, area] : cover)
      if (footprint > 0 && area >= p.storey_min_cover * footprint) {
        join_masses(up, low, uf, members);
        break;
      }
  }
}

// The masses in the order of their smallest part index, with their geometry.
void measure_masses(LevelMassing& L, const std::vector<PolygonMesh>& meshes, UnionFind& uf) {
  auto& P = L.parts;
  std::map<uint32_t, int> id_of_root;
  for (uint32_t i = 0; i < P.size(); ++i) {
    auto [it, fresh] = id_of_root.try_emplace(uf.find(i), static_cast<int>(L.masses.size()));
    if (fresh) L.masses.emplace_back();
    P[i].mass = it->second;
    L.masses[static_cast<size_t>(it->second)].parts.push_back(i);
  }
  for (MassMassing& m : L.masses) {
    m.z_min = std::numeric_limits<double>::infinity();
    m.z_max = -m.z_min;
    std::vector<mc::io::Polygon2> prints;
    for (uint32_t i : m.parts) {
      m.z_min = std::min(m.z_min, P[i].z_min), m.z_max = std::max(m.z_max, P[i].z_max);
      m.volume += P[i].volume;
      for (const auto& poly : P[i].footprint) prints.push_back(poly);
    }
    m.hull_volume =
        m.parts.size() == 1 ? P[m.parts[0]].hull_volume : convex_hull(vertices_of(m.parts, meshes)).volume;
    bool ok = false;
    const mc::io::MultiPolygon2 u = m.parts.size() == 1 ? P[m.parts[0]].footprint : union_of(prints, ok);
    m.footprint_area = m.parts.size() == 1 ? P[m.parts[0]].footprint_area : multipolygon_area(u);
    const PlanExtent e = plan_extent(outer_hull(u));
    m.width = e.width, m.length = e.length;
    m.grounded = std::any_of(m.parts.begin(), m.parts.end(), [&](uint32_t i) { return P[i].grounded; });
  }
}

// The masses' contacts: the parts' contacts across masses, by kind; the kind with the largest area.
void mass_contacts(LevelMassing& L) {
  const auto& P = L.parts;
  std::map<std::pair<int, int>, KindAreas> acc;
  for (uint32_t i = 0; i < P.size(); ++i)
    for (const Contact& c : P[i].contacts) {
      if (P[c.other].mass == P[i].mass) continue;
      auto& slot = acc[{P[i].mass, P[c.other].mass}][c.kind];
      slot.first += c.area;
      slot.second += c.above * c.area;
    }
  for (const auto& [key, kinds] : acc)
    L.masses[static_cast<size_t>(key.first)].contacts.push_back(
        contact_from(static_cast<uint32_t>(key.second), kinds));
}

}  // namespace

void group_masses(LevelMassing& L, const std::vector<PolygonMesh>& meshes, const MassingParams& p) {
  L.masses.clear();
  if (L.parts.empty()) return;
  classify_pieces(L.parts, p);
  UnionFind uf(static_cast<uint32_t>(L.parts.size()));
  join_bodies(L.parts, meshes, p, uf, false);
  attach_roofs_and_layers(L.parts, uf);
  join_bodies(L.parts, meshes, p, uf, true);
  join_storeys(L.parts, p, uf);
  measure_masses(L, meshes, uf);
  mass_contacts(L);
}

}  // namespace mc::massing
