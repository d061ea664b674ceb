#include "output/part_repair.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <unordered_map>

namespace mc::output {

namespace {

struct LocalMesh {
  PolygonMesh mesh;
  std::vector<int64_t> pool_id;  // mesh vertex -> pool id
};

// The faces as a mesh over the vertices they use, one mesh face per GridFace.
LocalMesh as_mesh(const std::vector<GridFace>& faces, const std::vector<Vec3>& pool) {
  LocalMesh m;
  std::unordered_map<int64_t, uint32_t> local;
  for (const GridFace& f : faces) {
    Polygon p;
    p.semantic = f.semantic;
    for (const auto& ring : f.rings) {
      std::vector<uint32_t> r;
      for (int64_t id : ring) {
        auto [it, fresh] = local.try_emplace(id, static_cast<uint32_t>(m.mesh.vertices.size()));
        if (fresh) {
          m.mesh.vertices.push_back(pool.at(static_cast<size_t>(id)));
          m.pool_id.push_back(id);
        }
        r.push_back(it->second);
      }
      p.rings.push_back(std::move(r));
    }
    m.mesh.faces.push_back(std::move(p));
  }
  return m;
}

Vec3 ring_normal(const std::vector<int64_t>& ring, const std::vector<Vec3>& pool) {
  Vec3 n;
  const Vec3& o = pool[ring[0]];
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec3 a = pool[ring[i]] - o, b = pool[ring[(i + 1) % ring.size()]] - o;
    n += {(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

bool visits_twice(const std::vector<int64_t>& ring) {
  std::vector<int64_t> s = ring;
  std::sort(s.begin(), s.end());
  return std::adjacent_find(s.begin(), s.end()) != s.end();
}

// A ring that visits vertices more than once, cut at those vertices into loops that do not.
std::vector<std::vector<int64_t>> simple_loops(const std::vector<int64_t>& ring) {
  std::vector<std::vector<int64_t>> loops;
  std::vector<int64_t> stack;
  for (int64_t v : ring) {
    auto at = std::find(stack.begin(), stack.end(), v);
    if (at != stack.end()) {
      loops.emplace_back(at, stack.end());
      stack.erase(at + 1, stack.end());
    } else {
      stack.push_back(v);
    }
  }
  loops.push_back(std::move(stack));
  loops.erase(std::remove_if(loops.begin(), loops.end(), [](const auto& l) { return l.size() < 3; }),
              loops.end());
  return loops;
}

// Is point p inside the ring, both projected along the normal's dominant axis?
bool inside_projected(const Vec3& p, const std::vector<int64_t>& ring, const std::vector<Vec3>& pool,
                      const Vec3& n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  auto uv = [&](const Vec3& q) {
    return ax >= ay && ax >= az ? std::pair{q.y, q.z} : ay >= az ? std::pair{q.z, q.x} : std::pair{q.x, q.y};
  };
  const auto [px, py] = uv(p);
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const auto [xi, yi] = uv(pool[ring[i]]);
    const auto [xj, yj] = uv(pool[ring[j]]);
    if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) in = !in;
  }
  return in;
}

// Repair 1: every ring cut into simple loops; loops turning like the face's outer ring are faces,
// the others holes of the face around them.
std::vector<GridFace> split_touching(const GridFace& f, const std::vector<Vec3>& pool) {
  const Vec3 n = ring_normal(f.rings[0], pool);
  std::vector<std::vector<int64_t>> outers, holes;
  for (const auto& ring : f.rings)
    for (auto& loop : simple_loops(ring))
      (dot(ring_normal(loop, pool), n) > 0 ? outers : holes).push_back(std::move(loop));
  std::vector<GridFace> out;
  for (auto& o : outers) out.push_back({{std::move(o)}, f.semantic, f.neighbour});
  if (out.empty()) return {f};
  for (auto& h : holes) {
    size_t host = 0;
    double largest = -1;
    for (size_t k = 0; k < out.size(); ++k) {
      const double area = norm(ring_normal(out[k].rings[0], pool));
      const auto& outer = out[k].rings[0];
      auto free = std::find_if(h.begin(), h.end(), [&](int64_t v) {
        return std::find(outer.begin(), outer.end(), v) == outer.end();
      });
      const bool contains = free != h.end() && inside_projected(pool[*free], outer, pool, n);
      if (contains && area > largest) host = k, largest = area;
    }
    out[host].rings.push_back(std::move(h));
  }
  return out;
}

// A ring passing within `tol` of one of its own vertices (not at that vertex's edges) gets the
// vertex inserted there: the ring then visits it twice, and split_touching cuts it into its lobes.
// A face of two lobes joined by a neck thinner than the grid (a kept corner a fraction of a
// millimetre from the face's own straight edge) otherwise folds across the neck when rounded.
// At most twice as many insertions as the ring had vertices, a bound fixed before the first one:
// in a ring smaller than `tol` (three vertices a grid step apart) each vertex lies within `tol` of
// the edges the last insertion made, so every insertion makes another.
bool pinch_ring(std::vector<int64_t>& ring, const std::vector<Vec3>& pool, double tol) {
  bool changed = false;
  const size_t limit = ring.size() * 2;
  for (size_t guard = 0; guard < limit; ++guard) {
    bool inserted = false;
    const size_t n = ring.size();
    for (size_t e = 0; e < n && !inserted; ++e) {
      const int64_t a = ring[e], b = ring[(e + 1) % n];
      const Vec3 &pa = pool[a], &pb = pool[b];
      const Vec3 ab = pb - pa;
      const double len2 = dot(ab, ab);
      if (!(len2 > 0)) continue;
      for (size_t k = 0; k < n; ++k) {
        const int64_t v = ring[k];
        if (v == a || v == b) continue;
        const double t = dot(pool[v] - pa, ab) / len2;
        if (t <= 0 || t >= 1) continue;
        if (norm(pool[v] - (pa + ab * t)) >= tol) continue;
        ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(e) + 1, v);
        inserted = changed = true;
        break;
      }
    }
    if (!inserted) break;
  }
  return changed;
}

// Every face with a ring pinched by pinch_ring, cut into its lobes. True when a face changed.
bool split_necks(std::vector<GridFace>& faces, const std::vector<Vec3>& pool, double tol) {
  bool changed = false;
  std::vector<GridFace> out;
  for (GridFace& f : faces) {
    bool pinched = false;
    for (auto& ring : f.rings) pinched |= pinch_ring(ring, pool, tol);
    if (!pinched) {
      out.push_back(std::move(f));
      continue;
    }
    changed = true;
    for (GridFace& g : split_touching(f, pool)) out.push_back(std::move(g));
  }
  faces = std::move(out);
  return changed;
}

// Repair 2: the face as triangles (each a face of its own), canonically, so that a face two
// parts share gets the same triangles in both. Empty when its rings cross each other.
std::vector<GridFace> triangles_of(const GridFace& f, const std::vector<Vec3>& pool) {
  std::vector<int64_t> ids;  // sorted: the local order is the pool order in every part
  for (const auto& ring : f.rings) ids.insert(ids.end(), ring.begin(), ring.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<Vec3> pts;
  for (int64_t id : ids) pts.push_back(pool[id]);
  std::vector<std::vector<uint32_t>> rings;
  for (const auto& ring : f.rings) {
    std::vector<uint32_t> r;
    for (int64_t id : ring)
      r.push_back(static_cast<uint32_t>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin()));
    rings.push_back(std::move(r));
  }
  std::vector<std::array<uint32_t, 3>> tris;
  if (!triangulate_polygon_canonical(rings, pts, tris)) {
    // A ring the grid folded across itself has no triangulation in its plane; a fan from its
    // smallest id (the same in every part that shares the face) may still close the shell
    // validly: the part's check decides.
    if (f.rings.size() != 1 || f.rings[0].size() < 3) return {};
    const std::vector<int64_t>& r = f.rings[0];
    const size_t s = static_cast<size_t>(std::min_element(r.begin(), r.end()) - r.begin());
    std::vector<GridFace> out;
    for (size_t k = 1; k + 1 < r.size(); ++k)
      out.push_back({{{r[s], r[(s + k) % r.size()], r[(s + k + 1) % r.size()]}}, f.semantic, f.neighbour});
    return out;
  }
  std::vector<GridFace> out;
  for (const auto& t : tris) out.push_back({{{ids[t[0]], ids[t[1]], ids[t[2]]}}, f.semantic, f.neighbour});
  return out;
}

// Repair 0: a shell the grid left open. Where planes (nearly) meet in one line or point, the
// carving's cells between them are slivers; rounding to the grid collapses them below val3dity's
// snap distance, where two vertices are one. A ring then repeats a vertex (102), runs along an edge
// and straight back (a spike), or keeps two distinct points (101), and the faces beside the sliver
// meet an edge at a vertex the other face lacks (a T-junction, 302). The rings are cleaned as
// val3dity sees them (vertices within the snap distance are one) and each unmatched edge gets the
// part's vertices that lie on it (docs/output-format.md §Validity).
bool on_line(const Vec3& a, const Vec3& b, const Vec3& p, double tol) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  if (!(l2 > 0)) return false;
  return norm(cross(ab, p - a)) <= tol * std::sqrt(l2);
}

// `same[i]`: the vertex (merged) that ring entry i is to val3dity; `at(m)` its position.
bool clean_ring(std::vector<int64_t>& ring, const std::function<uint32_t(int64_t)>& same,
                const std::function<const Vec3&(uint32_t)>& at, double tol) {
  bool changed = false;
  for (bool again = true; again && ring.size() >= 2;) {
    again = false;
    for (size_t i = 0; i < ring.size() && ring.size() >= 2; ++i) {
      const size_t n = ring.size();
      const uint32_t a = same(ring[(i + n - 1) % n]), b = same(ring[i]), c = same(ring[(i + 1) % n]);
      // b repeats a (one vertex to val3dity), or is the tip of a spike a -> b -> back towards a
      bool drop = a == b;
      if (!drop && n >= 3)
        drop = a == c || (on_line(at(a), at(b), at(c), tol) && dot(at(b) - at(a), at(c) - at(b)) < 0);
      if (!drop) continue;
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      changed = again = true;
      break;
    }
  }
  return changed;
}

bool close_on_grid(std::vector<GridFace>& faces, const std::vector<Vec3>& pool, double snap) {
  // The vertices merged as check_solid merges them: same order (as_mesh), same snap distance.
  const LocalMesh m = as_mesh(faces, pool);
  std::vector<Vec3> merged;
  const std::vector<uint32_t> mid = merge_vertices(m.mesh.vertices, snap, merged);
  std::unordered_map<int64_t, uint32_t> merged_of;
  std::vector<int64_t> first_id(merged.size(), -1);  // a pool id of each merged vertex
  for (size_t i = 0; i < mid.size(); ++i) {
    merged_of.emplace(m.pool_id[i], mid[i]);
    if (first_id[mid[i]] < 0) first_id[mid[i]] = m.pool_id[i];
  }
  const std::function<uint32_t(int64_t)> same = [&](int64_t id) { return merged_of.at(id); };
  const std::function<const Vec3&(uint32_t)> at = [&](uint32_t v) -> const Vec3& { return merged[v]; };
  bool changed = false;
  for (GridFace& f : faces) {
    for (auto& ring : f.rings) changed |= clean_ring(ring, same, at, snap);
    std::vector<std::vector<int64_t>> kept;
    for (size_t r = 0; r < f.rings.size(); ++r) {
      std::set<uint32_t> distinct;
      for (int64_t id : f.rings[r]) distinct.insert(same(id));
      if (distinct.size() >= 3) kept.push_back(std::move(f.rings[r]));
      else if (r == 0) break;  // the outer ring collapsed: the face is gone
    }
    changed |= kept.size() != f.rings.size();
    f.rings = std::move(kept);
  }
  faces.erase(std::remove_if(faces.begin(), faces.end(), [](const GridFace& f) { return f.rings.empty(); }),
              faces.end());
  // The vertices merged are written as one: val3dity merges two vertices exactly the snap distance
  // apart or not as the file's coordinates round, so the part must not need it to.
  for (GridFace& f : faces)
    for (auto& ring : f.rings)
      for (int64_t& id : ring) {
        const int64_t one = first_id[same(id)];
        changed |= one != id;
        id = one;
      }
  for (int round = 0; round < 4; ++round) {
    std::set<std::pair<uint32_t, uint32_t>> edges;
    std::set<uint32_t> used;
    for (const GridFace& f : faces)
      for (const auto& ring : f.rings)
        for (size_t i = 0; i < ring.size(); ++i) {
          edges.emplace(same(ring[i]), same(ring[(i + 1) % ring.size()]));
          used.insert(same(ring[i]));
        }
    bool inserted = false;
    for (GridFace& f : faces)
      for (auto& ring : f.rings) {
        std::vector<int64_t> next;
        for (size_t i = 0; i < ring.size(); ++i) {
          const uint32_t u = same(ring[i]), v = same(ring[(i + 1) % ring.size()]);
          next.push_back(ring[i]);
          if (edges.count({v, u})) continue;
          const Vec3 d = at(v) - at(u);
          const double l2 = dot(d, d);
          std::vector<std::pair<double, uint32_t>> on;
          for (uint32_t w : used) {
            if (w == u || w == v) continue;
            const double t = dot(at(w) - at(u), d) / l2;
            if (t > 0 && t < 1 && on_line(at(u), at(v), at(w), snap)) on.emplace_back(t, w);
          }
          std::sort(on.begin(), on.end());
          for (const auto& [t, w] : on) next.push_back(first_id[w]);
          inserted |= !on.empty();
        }
        ring = std::move(next);
      }
    if (!inserted) break;
    changed = true;
  }
  return changed;
}

// Faces of a rule that no change of the face alone can fix (vertices within the snap distance):
// those need the level's vertices clustered.
bool face_repairable(int code) {
  return code == solid_code::kRingSelfIntersection || code == solid_code::kNonPlanarPolygon ||
         code == solid_code::kNonPlanarNormals || code == solid_code::kRingCollapsed ||
         code == solid_code::kIntersectionRings || code == solid_code::kOrientationRingsSame;
}

}  // namespace

size_t triangulate_bent_shared_faces(std::vector<GridFace>& faces, const std::vector<Vec3>& pool) {
  size_t replaced = 0;
  std::vector<GridFace> out;
  for (GridFace& f : faces) {
    if (f.neighbour >= 0 && !(f.rings.size() == 1 && f.rings[0].size() == 3)) {
      std::vector<Vec3> pts;
      for (const auto& ring : f.rings)
        for (int64_t id : ring) pts.push_back(pool[id]);
      if (!exactly_coplanar(pts)) {
        std::vector<GridFace> tris = triangles_of(f, pool);
        if (!tris.empty()) {
          ++replaced;
          for (auto& t : tris) out.push_back(std::move(t));
          continue;
        }
      }
    }
    out.push_back(std::move(f));
  }
  faces = std::move(out);
  return replaced;
}

namespace {

// A face's rings, each started at its smallest id, in a canonical order: equal keys are the same
// polygon with the same orientation.
std::vector<std::vector<int64_t>> face_key(const GridFace& f, bool reversed) {
  std::vector<std::vector<int64_t>> key;
  for (auto ring : f.rings) {
    if (reversed) std::reverse(ring.begin(), ring.end());
    std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
    key.push_back(std::move(ring));
  }
  std::sort(key.begin() + (key.empty() ? 0 : 1), key.end());  // the outer ring stays first
  return key;
}

// The faces of `faces` shared with part `other`, as sorted keys.
std::vector<std::vector<std::vector<int64_t>>> shared_keys(const std::vector<GridFace>& faces, int32_t other,
                                                           bool reversed) {
  std::vector<std::vector<std::vector<int64_t>>> keys;
  for (const GridFace& f : faces)
    if (f.neighbour == other) keys.push_back(face_key(f, reversed));
  std::sort(keys.begin(), keys.end());
  return keys;
}

// `to`'s faces with the faces it shares with `from_id` replaced by reversed copies of `from`'s
// faces shared with `to_id` (their semantic label: that of `to`'s first shared face).
std::vector<GridFace> with_copy(const std::vector<GridFace>& to, int32_t to_id,
                                const std::vector<GridFace>& from, int32_t from_id) {
  std::vector<GridFace> out;
  int32_t semantic = -1;
  bool first = true;
  for (const GridFace& f : to) {
    if (f.neighbour == from_id) {
      if (first) semantic = f.semantic, first = false;
      continue;
    }
    out.push_back(f);
  }
  for (const GridFace& f : from)
    if (f.neighbour == to_id) {
      GridFace g = f;
      for (auto& ring : g.rings) std::reverse(ring.begin(), ring.end());
      g.neighbour = from_id;
      g.semantic = semantic;
      out.push_back(std::move(g));
    }
  return out;
}

}  // namespace

std::vector<size_t> align_shared_faces(std::vector<std::vector<GridFace>>& parts,
                                       const std::vector<bool>& repaired, const std::vector<Vec3>& pool) {
  std::set<size_t> changed;
  for (size_t j = 0; j < parts.size(); ++j) {
    if (j >= repaired.size() || !repaired[j]) continue;
    std::set<int32_t> others;
    for (const GridFace& f : parts[j])
      if (f.neighbour >= 0 && static_cast<size_t>(f.neighbour) < parts.size() &&
          static_cast<size_t>(f.neighbour) != j)
        others.insert(f.neighbour);
    const int32_t jj = static_cast<int32_t>(j);
    for (int32_t k : others) {
      if (shared_keys(parts[j], k, false) == shared_keys(parts[k], jj, true)) continue;
      std::vector<GridFace> to_k = with_copy(parts[k], k, parts[j], jj);
      if (grid_solid_defect(to_k, pool).empty()) {
        parts[k] = std::move(to_k);
        changed.insert(static_cast<size_t>(k));
        continue;
      }
      std::vector<GridFace> to_j = with_copy(parts[j], jj, parts[k], k);
      if (grid_solid_defect(to_j, pool).empty()) {
        parts[j] = std::move(to_j);
        changed.insert(j);
      }
    }
  }
  return {changed.begin(), changed.end()};
}

std::string grid_solid_defect(const std::vector<GridFace>& faces, const std::vector<Vec3>& pool,
                              SolidCheck* check) {
  const LocalMesh m = as_mesh(faces, pool);
  SolidCheck c = check_solid(m.mesh, val3dity_tolerances(), false);
  std::string defect;
  if (!c.errors.empty())
    defect = std::to_string(c.errors[0].code) + " " + c.errors[0].name + ": " + c.errors[0].message;
  if (check) *check = std::move(c);
  return defect;
}

namespace {

// Repairs 1 and 2 on the faces val3dity's rules name, two rounds, checked after each.
void repair_faces(PartRepair& r, SolidCheck& c, const std::vector<Vec3>& pool) {
  for (int round = 0; round < 2 && !r.defect.empty(); ++round) {
    std::set<size_t> bad;
    for (const auto& [fi, code] : c.bad_faces)
      if (face_repairable(code)) bad.insert(fi);
    if (bad.empty()) break;
    std::vector<GridFace> next;
    bool changed = false;
    for (size_t i = 0; i < r.faces.size(); ++i) {
      const GridFace& f = r.faces[i];
      std::vector<GridFace> pieces;
      if (bad.count(i)) {
        const bool touching = std::any_of(f.rings.begin(), f.rings.end(), visits_twice);
        if (round == 0 && touching) pieces = split_touching(f, pool);
        else if (round == 1 || !touching) pieces = triangles_of(f, pool);
      }
      if (pieces.empty()) {
        next.push_back(f);
        continue;
      }
      changed = true;
      ++r.split_faces;
      for (auto& p : pieces) next.push_back(std::move(p));
    }
    if (!changed) continue;
    r.repaired = true;
    r.faces = std::move(next);
    r.defect = grid_solid_defect(r.faces, pool, &c);
  }
}

}  // namespace

PartRepair check_and_repair(std::vector<GridFace> faces, const std::vector<Vec3>& pool, double step) {
  PartRepair r;
  r.faces = std::move(faces);
  auto valid = [](PartRepair& x, SolidCheck& check) {
    x.shell = std::move(check.shell);
    return std::move(x);
  };
  SolidCheck c;
  r.defect = grid_solid_defect(r.faces, pool, &c);
  if (r.defect.empty()) return valid(r, c);
  std::vector<GridFace> original = r.faces;
  repair_faces(r, c, pool);
  if (r.defect.empty()) return valid(r, c);
  // Repair 0, when the face repairs alone leave the part invalid: the shell closed on the grid
  // first (rings cleaned as val3dity merges their vertices, T-junctions filled), then the face
  // repairs again.
  std::vector<GridFace> necked = original;
  if (close_on_grid(original, pool, val3dity_tolerances().snap)) {
    PartRepair closed;
    closed.faces = std::move(original);
    closed.repaired = true;
    SolidCheck cc;
    closed.defect = grid_solid_defect(closed.faces, pool, &cc);
    repair_faces(closed, cc, pool);
    if (closed.defect.empty()) return valid(closed, cc);
  }
  // Then faces whose ring comes within a grid step of itself, cut into their lobes (docs/
  // output-format.md §Repairs), and repairs 1 and 2 again.
  if (!split_necks(necked, pool, std::max(step, val3dity_tolerances().snap) * 1.5)) return r;
  PartRepair cut;
  cut.faces = std::move(necked);
  cut.repaired = true;
  SolidCheck nc;
  cut.defect = grid_solid_defect(cut.faces, pool, &nc);
  repair_faces(cut, nc, pool);
  if (cut.defect.empty()) return valid(cut, nc);
  return r;
}

}  // namespace mc::output
