#include "core/soup.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Eigenvalues>
#include <list>

#include "core/cdt_domains.hpp"
#include "core/plane.hpp"
#include "core/union_find.hpp"

namespace mc {

FaceGeometry face_geometry(const PolygonMesh& mesh, const Polygon& face) {
  FaceGeometry g;
  if (face.rings.empty()) return g;
  const Vec3 outer = ring_area_vector(mesh.vertices, face.rings[0]);
  g.normal = normalized(outer);
  double area = 0.5 * norm(outer);
  for (size_t r = 1; r < face.rings.size(); ++r)
    area -= 0.5 * std::abs(dot(ring_area_vector(mesh.vertices, face.rings[r]), g.normal));
  g.area = std::max(0.0, area);
  return g;
}

Vec3 bbox_center(const PolygonMesh& mesh) {
  BBox box;
  for (const Polygon& f : mesh.faces)
    for (const auto& ring : f.rings)
      for (uint32_t v : ring)
        if (v < mesh.vertices.size()) box.add(mesh.vertices[v]);
  if (!box.valid())
    for (const Vec3& v : mesh.vertices) box.add(v);
  return box.valid() ? box.center() : Vec3{};
}

void translate(PolygonMesh& mesh, Vec3 offset) {
  for (Vec3& v : mesh.vertices) v += offset;
}

namespace {

struct CellKey {
  int64_t x, y, z;
  bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct CellHash {
  size_t operator()(const CellKey& k) const {
    uint64_t h = static_cast<uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<uint64_t>(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};

// Maps every finite vertex to its cluster representative (smallest index within merge_tol,
// transitively). Non-finite vertices map to themselves and are excluded by the caller.
std::vector<uint32_t> merge_vertices(const std::vector<Vec3>& vs, const std::vector<bool>& ok, double tol) {
  UnionFind uf(vs.size());
  const bool exact = !(tol > 0);
  const double cell = exact ? 1.0 : tol;
  std::unordered_map<CellKey, std::vector<uint32_t>, CellHash> grid;
  grid.reserve(vs.size());
  auto key_of = [&](const Vec3& p) {
    return CellKey{static_cast<int64_t>(std::floor(p.x / cell)), static_cast<int64_t>(std::floor(p.y / cell)),
                   static_cast<int64_t>(std::floor(p.z / cell))};
  };
  for (uint32_t i = 0; i < vs.size(); ++i) {
    if (!ok[i]) continue;
    const CellKey k = key_of(vs[i]);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = grid.find({k.x + dx, k.y + dy, k.z + dz});
          if (it == grid.end()) continue;
          for (uint32_t j : it->second) {
            const bool same = exact ? vs[i] == vs[j] : norm(vs[i] - vs[j]) <= tol;
            if (same) uf.unite_low(i, j);
          }
        }
    grid[k].push_back(i);
  }
  std::vector<uint32_t> rep(vs.size());
  for (uint32_t i = 0; i < vs.size(); ++i) rep[i] = uf.find(i);
  return rep;
}

// Ring rotated to start at its smallest index, in the lexicographically smaller direction:
// equal for two rings that are the same polygon whatever the start and orientation.
std::vector<uint32_t> canonical_ring(const std::vector<uint32_t>& r) {
  const size_t n = r.size();
  const size_t m = static_cast<size_t>(std::min_element(r.begin(), r.end()) - r.begin());
  std::vector<uint32_t> fwd(n), bwd(n);
  for (size_t i = 0; i < n; ++i) {
    fwd[i] = r[(m + i) % n];
    bwd[i] = r[(m + n - i) % n];
  }
  return std::min(fwd, bwd);
}

}  // namespace

namespace {

// What cleaning did, for the problems list.
struct CleanCounts {
  size_t nonfinite = 0, merged = 0, bad_index = 0, repeat = 0, bad_outer = 0, bad_hole = 0, dup = 0,
         unused = 0;
};

// A ring with its vertices replaced by their representatives and consecutive repeats removed;
// empty when it is degenerate: fewer than 3 distinct points, or an area below what a ring of width
// merge_tol could have, or negligible relative to the model size (`area_floor`).
std::vector<uint32_t> clean_ring(const std::vector<uint32_t>& in, const std::vector<uint32_t>& rep,
                                 const std::vector<Vec3>& vertices, double merge_tol, double area_floor,
                                 size_t& repeats) {
  std::vector<uint32_t> ring;
  for (uint32_t v : in) {
    const uint32_t m = rep[v];
    if (!ring.empty() && ring.back() == m) {
      ++repeats;
      continue;
    }
    ring.push_back(m);
  }
  while (ring.size() > 1 && ring.front() == ring.back()) {
    ring.pop_back();
    ++repeats;
  }
  std::vector<uint32_t> distinct = ring;
  std::sort(distinct.begin(), distinct.end());
  if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3) return {};
  double max_edge = 0;
  for (size_t i = 0; i < ring.size(); ++i)
    max_edge = std::max(max_edge, norm(vertices[ring[(i + 1) % ring.size()]] - vertices[ring[i]]));
  const double area = 0.5 * norm(ring_area_vector(vertices, ring));
  if (area <= std::max(area_floor, merge_tol * max_edge)) return {};
  return ring;
}

// A face's identity up to ring rotation and hole order: duplicate faces have equal keys.
std::vector<uint32_t> face_key(const Polygon& g) {
  std::vector<uint32_t> key = canonical_ring(g.rings[0]);
  std::vector<std::vector<uint32_t>> holes;
  for (size_t r = 1; r < g.rings.size(); ++r) holes.push_back(canonical_ring(g.rings[r]));
  std::sort(holes.begin(), holes.end());
  for (const auto& h : holes) {
    key.push_back(UINT32_MAX);
    key.insert(key.end(), h.begin(), h.end());
  }
  return key;
}

// Compact: keep the used vertices in their original order, renumber the faces' rings.
void compact_vertices(const PolygonMesh& mesh, const std::vector<bool>& finite,
                      const std::vector<uint32_t>& rep, std::vector<Polygon> kept, PolygonMesh& out,
                      size_t& unused) {
  const size_t nv = mesh.vertices.size();
  std::vector<uint32_t> new_index(nv, UINT32_MAX);
  for (const Polygon& f : kept)
    for (const auto& ring : f.rings)
      for (uint32_t v : ring) new_index[v] = 0;
  for (size_t i = 0; i < nv; ++i) {
    if (new_index[i] == 0) {
      new_index[i] = static_cast<uint32_t>(out.vertices.size());
      out.vertices.push_back(mesh.vertices[i]);
    } else if (finite[i] && rep[i] == i) {
      ++unused;
    }
  }
  for (Polygon& f : kept)
    for (auto& ring : f.rings)
      for (uint32_t& v : ring) v = new_index[v];
  out.faces = std::move(kept);
}

void report_cleaning(const CleanCounts& n, std::vector<std::string>& problems) {
  auto report = [&](size_t k, const char* what) {
    if (k) problems.push_back(std::to_string(k) + " " + what);
  };
  report(n.nonfinite, "vertices with non-finite coordinates dropped");
  report(n.bad_index, "faces dropped: non-finite vertex, bad index or no ring");
  report(n.merged, "duplicate vertices merged");
  report(n.repeat, "repeated consecutive ring indices removed");
  report(n.bad_outer, "faces dropped: degenerate outer ring (< 3 points or ~zero area)");
  report(n.bad_hole, "degenerate hole rings dropped");
  report(n.dup, "duplicate faces dropped");
  report(n.unused, "unused vertices removed");
}

}  // namespace

PolygonMesh clean_soup(const PolygonMesh& mesh, double merge_tol, std::vector<std::string>* problems) {
  const size_t nv = mesh.vertices.size();
  CleanCounts n;
  std::vector<bool> finite(nv);
  BBox box;
  for (size_t i = 0; i < nv; ++i) {
    finite[i] = is_finite(mesh.vertices[i]);
    if (!finite[i]) ++n.nonfinite;
    else box.add(mesh.vertices[i]);
  }
  const std::vector<uint32_t> rep = merge_vertices(mesh.vertices, finite, merge_tol);
  for (size_t i = 0; i < nv; ++i) n.merged += finite[i] && rep[i] != i;
  const double diag = box.diagonal();
  const double area_floor = 1e-14 * diag * diag;
  PolygonMesh out;
  out.semantic_labels = mesh.semantic_labels;
  std::set<std::vector<uint32_t>> seen;
  std::vector<Polygon> kept;
  for (const Polygon& f : mesh.faces) {
    bool usable = !f.rings.empty();
    for (const auto& ring : f.rings)
      for (uint32_t v : ring)
        if (v >= nv || !finite[v]) usable = false;
    if (!usable) {
      ++n.bad_index;
      continue;
    }
    Polygon g;
    g.semantic = f.semantic;
    for (size_t r = 0; r < f.rings.size(); ++r) {
      std::vector<uint32_t> ring =
          clean_ring(f.rings[r], rep, mesh.vertices, merge_tol, area_floor, n.repeat);
      if (ring.empty()) {
        if (r == 0) {
          ++n.bad_outer;
          break;
        }
        ++n.bad_hole;
        continue;
      }
      g.rings.push_back(std::move(ring));
    }
    if (g.rings.empty()) continue;  // the outer ring was degenerate: its holes go with it
    if (!seen.insert(face_key(g)).second) {
      ++n.dup;
      continue;
    }
    kept.push_back(std::move(g));
  }
  compact_vertices(mesh, finite, rep, std::move(kept), out, n.unused);
  if (problems) report_cleaning(n, *problems);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Triangulation: constrained Delaunay on the best-fit plane projection, odd nesting = inside.

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr uint32_t kNoVertex = UINT32_MAX;
struct VertexInfo {
  uint32_t id = kNoVertex;  // soup vertex; kNoVertex for points created at constraint crossings
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;  // nesting level
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: crossing constraints (self-intersecting rings) are split, not rejected.
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Nesting level of every face (core/cdt_domains.hpp).
void mark_domains(CDT& cdt) {
  mark_nesting(cdt, [](CDT::Face_handle f) -> int& { return f->info(); });
}

// Best-fit normal of a face: the Newell normal of the outer ring, or the smallest principal
// axis of all ring points when the ring's area vector vanishes (e.g. a figure-eight ring).
Vec3 fit_normal(const std::vector<Vec3>& vs, const Polygon& f) {
  Vec3 n = normalized(ring_area_vector(vs, f.rings[0]));
  if (norm(n) > 0.5) return n;
  std::vector<Vec3> points;
  for (const auto& r : f.rings)
    for (uint32_t v : r) points.push_back(vs[v]);
  Vec3 c;
  const PrincipalAxes axes = principal_axes(centred_covariance(points, c));
  if (axes.eigenvalues(1) <= 0) return {};  // collinear: no plane
  return normalized(axes.normal);
}

}  // namespace

TriangleSoup triangulate(const PolygonMesh& mesh) {
  TriangleSoup soup;
  soup.vertices = mesh.vertices;
  for (uint32_t fi = 0; fi < mesh.faces.size(); ++fi) {
    const Polygon& f = mesh.faces[fi];
    if (f.rings.empty() || f.rings[0].size() < 3) continue;
    if (f.rings.size() == 1 && f.rings[0].size() == 3) {  // common case: already a triangle
      const auto& r = f.rings[0];
      if (r[0] != r[1] && r[1] != r[2] && r[0] != r[2]) {
        soup.triangles.push_back({r[0], r[1], r[2]});
        soup.source_face.push_back(fi);
      }
      continue;
    }
    const Vec3 n = fit_normal(mesh.vertices, f);
    if (!(norm(n) > 0.5)) continue;
    // Orthonormal basis (u, v, n) with u x v = n, so CCW in 2D is the outer ring's orientation.
    const Vec3 a = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalized(cross(a, n));
    const Vec3 v = cross(n, u);
    const Vec3 o = mesh.vertices[f.rings[0][0]];
    double offset = 0;  // mean height over the plane through o, for lifting new vertices
    size_t count = 0;
    CDT cdt;
    for (const auto& ring : f.rings) {
      std::vector<CDT::Vertex_handle> hs;
      for (uint32_t vi : ring) {
        const Vec3 d = mesh.vertices[vi] - o;
        offset += dot(d, n);
        ++count;
        CDT::Vertex_handle h = cdt.insert(K::Point_2(dot(d, u), dot(d, v)));
        if (h->info().id == kNoVertex) h->info().id = vi;  // first 3D vertex at this 2D spot
        hs.push_back(h);
      }
      for (size_t i = 0; i < hs.size(); ++i) {
        CDT::Vertex_handle p = hs[i], q = hs[(i + 1) % hs.size()];
        if (p != q) cdt.insert_constraint(p, q);
      }
    }
    offset /= static_cast<double>(count);
    mark_domains(cdt);
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
      if (fh->info() % 2 != 1) continue;
      std::array<uint32_t, 3> t;
      for (int k = 0; k < 3; ++k) {
        VertexInfo& info = fh->vertex(k)->info();
        if (info.id == kNoVertex) {  // constraint crossing: lift onto the mean plane
          const K::Point_2& p = fh->vertex(k)->point();
          info.id = static_cast<uint32_t>(soup.vertices.size());
          soup.vertices.push_back(o + u * p.x() + v * p.y() + n * offset);
        }
        t[k] = info.id;
      }
      soup.triangles.push_back(t);
      soup.source_face.push_back(fi);
    }
  }
  return soup;
}

}  // namespace mc
