#include "core/solid_validation.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Modifier_base.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_incremental_builder_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/linear_least_squares_fitting_3.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <tuple>
#include <cmath>
#include <list>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/cdt_domains.hpp"
#include "core/geometry.hpp"
#include "core/hull.hpp"
#include "core/union_find.hpp"

namespace mc {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct FaceInfo {
  int nesting = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Constraints that cross (a bow-tie, two rings crossing) throw instead of being split: that is
// exactly the ring self-intersection test.
using CDT =
    CGAL::Constrained_Delaunay_triangulation_2<K, Tds,
                                               CGAL::No_constraint_intersection_requiring_constructions_tag>;

std::string fmt(const Vec3& p) {
  std::ostringstream o;
  o.precision(12);
  o << "(" << p.x << " " << p.y << " " << p.z << ")";
  return o.str();
}

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

// One error per code: the first occurrence described, the others counted.
class ErrorLog {
 public:
  void add(int code, const std::string& message) {
    auto [it, fresh] = first_.try_emplace(code, message);
    ++count_[code];
    (void)it, (void)fresh;
  }
  bool has(int code) const { return count_.count(code) > 0; }
  // Nothing logged except `code`.
  bool only(std::initializer_list<int> codes) const {
    for (const auto& [code, n] : count_)
      if (std::find(codes.begin(), codes.end(), code) == codes.end()) return false;
    return true;
  }
  std::vector<SolidError> take() const {
    std::vector<SolidError> out;
    for (const auto& [code, msg] : first_) {
      const size_t n = count_.at(code);
      out.push_back(
          {code, solid_error_name(code), n > 1 ? msg + " (and " + std::to_string(n - 1) + " more)" : msg});
    }
    return out;
  }

 private:
  std::map<int, std::string> first_;  // ordered by code: deterministic reports
  std::map<int, size_t> count_;
};

// Least-squares plane of points: centroid and the covariance's smallest eigenvector.
Plane fit_plane(const std::vector<Vec3>& pts) {
  Vec3 c;
  Plane pl;
  pl.n = principal_axes(centred_covariance(pts, c)).normal;
  pl.d = -dot(pl.n, c);
  return pl;
}

// Newell normal of a ring (its length is twice the ring's area).
Vec3 newell(const std::vector<uint32_t>& ring, const std::vector<Vec3>& v) {
  return ring_area_vector(v, ring);
}

// Faces at odd nesting depth from the infinite face are inside the polygon (holes excluded;
// core/cdt_domains.hpp).
void mark_domains(CDT& cdt) {
  mark_nesting(cdt, [](CDT::Face_handle f) -> int& { return f->info().nesting; });
}

struct Frame {
  Vec3 o, u, v;
  K::Point_2 operator()(const Vec3& p) const {
    const Vec3 d = p - o;
    return {dot(d, u), dot(d, v)};
  }
};

Frame frame_for(const Vec3& origin, const Vec3& normal) {
  const Vec3 n = normalized(normal);
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(a, n));
  return {origin, u, cross(n, u)};  // (u, v, n) right-handed: CCW around n is CCW in (u, v)
}

void insert_ring(CDT& cdt, const std::vector<uint32_t>& ring, const std::vector<Vec3>& pts, const Frame& f) {
  std::vector<CDT::Vertex_handle> vh;
  for (uint32_t id : ring) {
    CDT::Vertex_handle h = cdt.insert(f(pts[id]));
    h->info() = id;
    vh.push_back(h);
  }
  for (size_t i = 0; i < vh.size(); ++i) {
    CDT::Vertex_handle a = vh[i], b = vh[(i + 1) % vh.size()];
    if (a != b) cdt.insert_constraint(a, b);
  }
}

double signed_area_2d(const std::vector<uint32_t>& ring, const std::vector<Vec3>& pts, const Frame& f) {
  double a = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const K::Point_2 p = f(pts[ring[i]]), q = f(pts[ring[(i + 1) % ring.size()]]);
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a / 2;
}

// Triangulates one planar face with holes in its plane; ring problems go to `log`.
void triangulate_face(const std::vector<std::vector<uint32_t>>& rings, const std::vector<Vec3>& pts,
                      const Vec3& normal, size_t face, ErrorLog& log,
                      std::vector<std::array<uint32_t, 3>>& out) {
  const Frame f = frame_for(pts[rings[0][0]], normal);
  const std::string where = "face " + std::to_string(face);
  for (size_t r = 0; r < rings.size(); ++r) {
    CDT single;
    try {
      insert_ring(single, rings[r], pts, f);
    } catch (const CDT::Intersection_of_constraints_exception&) {
      log.add(solid_code::kRingSelfIntersection, where + ", ring " + std::to_string(r) + " crosses itself");
      return;
    }
    if (r > 0 && signed_area_2d(rings[r], pts, f) > 0)
      log.add(solid_code::kOrientationRingsSame,
              where + ": inner ring " + std::to_string(r) + " has the outer ring's orientation");
  }
  CDT cdt;
  try {
    for (const auto& ring : rings) insert_ring(cdt, ring, pts, f);
  } catch (const CDT::Intersection_of_constraints_exception&) {
    log.add(solid_code::kIntersectionRings, where + ": its rings cross each other");
    return;
  }
  mark_domains(cdt);
  for (auto fh : cdt.finite_face_handles()) {
    if (fh->info().nesting % 2 != 1) continue;
    out.push_back({fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()});  // CCW in (u, v)
  }
}

// The plane val3dity projects a face onto: the least-squares plane of the points (CGAL's fit
// over points), with normal components below 1e-12 set to zero; its to_2d() gives the 2D frame.
K::Plane_3 val3dity_plane(const std::vector<K::Point_3>& pts) {
  K::Plane_3 p;
  CGAL::linear_least_squares_fitting_3(pts.begin(), pts.end(), p, CGAL::Dimension_tag<0>());
  const auto zero = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
  return K::Plane_3(zero(p.a()), zero(p.b()), zero(p.c()), p.d());
}

// A face's rings projected as val3dity projects them for its ring and polygon rules: onto the
// least-squares plane of all the face's points.
std::vector<CGAL::Polygon_2<K>> projected_rings(const std::vector<std::vector<uint32_t>>& rings,
                                                const std::vector<K::Point_3>& local) {
  std::vector<K::Point_3> all;
  for (const auto& r : rings)
    for (uint32_t v : r) all.push_back(local[v]);
  const K::Plane_3 pl = val3dity_plane(all);
  std::vector<CGAL::Polygon_2<K>> out(rings.size());
  for (size_t i = 0; i < rings.size(); ++i)
    for (uint32_t v : rings[i]) out[i].push_back(pl.to_2d(local[v]));
  return out;
}

// val3dity's ring rule in a face's plane (104): each projected ring is a simple polygon with area.
bool rings_simple(const std::vector<CGAL::Polygon_2<K>>& rings) {
  for (const auto& pg : rings)
    if (!pg.is_simple() || pg.orientation() == CGAL::COLLINEAR) return false;
  return true;
}

// A face triangulated as val3dity triangulates it (Surface::construct_ct_one_face): constrained
// Delaunay in the least-squares plane of its outer ring, each ring's edges inserted in turn (both
// ends, then the constraint), triangles in the triangulation's order, turning like the outer
// ring. A triangle ring is its own triangle. False when the rings cross (reported elsewhere).
bool val3dity_triangles(const std::vector<std::vector<uint32_t>>& rings, const std::vector<K::Point_3>& local,
                        std::vector<std::array<uint32_t, 3>>& out) {
  out.clear();
  if (rings.size() == 1 && rings[0].size() == 3) {
    out.push_back({rings[0][0], rings[0][1], rings[0][2]});
    return true;
  }
  std::vector<K::Point_3> outer;
  for (uint32_t v : rings[0]) outer.push_back(local[v]);
  const K::Plane_3 pl = val3dity_plane(outer);
  CGAL::Polygon_2<K> outer_2d;
  for (const auto& p : outer) outer_2d.push_back(pl.to_2d(p));
  const bool reversed = !outer_2d.is_counterclockwise_oriented();
  CDT cdt;
  try {
    for (const auto& ring : rings)
      for (size_t i = 0; i < ring.size(); ++i) {
        const uint32_t a = ring[i], b = ring[(i + 1) % ring.size()];
        CDT::Vertex_handle va = cdt.insert(pl.to_2d(local[a]));
        va->info() = a;
        CDT::Vertex_handle vb = cdt.insert(pl.to_2d(local[b]));
        vb->info() = b;
        if (va != vb) cdt.insert_constraint(va, vb);
      }
  } catch (const CDT::Intersection_of_constraints_exception&) { return false; }
  mark_domains(cdt);
  for (auto fh : cdt.finite_face_handles()) {
    if (fh->info().nesting % 2 != 1) continue;
    const uint32_t a = fh->vertex(0)->info(), b = fh->vertex(1)->info(), c = fh->vertex(2)->info();
    out.push_back(reversed ? std::array<uint32_t, 3>{a, c, b} : std::array<uint32_t, 3>{a, b, c});
  }
  return true;
}

// val3dity's normals rule (204) on a face's triangles: the largest angle between the first
// triangle's normal and another's.
double triangle_normals_deviation_deg(const std::vector<std::array<uint32_t, 3>>& tris,
                                      const std::vector<K::Point_3>& local) {
  if (tris.size() < 2) return 0;
  std::optional<K::Vector_3> first;
  double worst = 0;
  for (const auto& t : tris) {
    const K::Point_3 &a = local[t[0]], &b = local[t[1]], &c = local[t[2]];
    K::Vector_3 n = CGAL::cross_product(b - a, c - a);
    const double len = std::sqrt(n.squared_length());
    if (!(len > 0)) return 180;  // a triangle without area: its normal is anything
    n = n / len;
    if (!first) {
      first = n;
      continue;
    }
    const double angle =
        std::atan2(std::sqrt(CGAL::cross_product(*first, n).squared_length()), *first * n) * 180 / M_PI;
    worst = std::max(worst, angle);
  }
  return worst;
}

Mesh to_mesh(const TriangleShell& s, bool& ok) {
  std::vector<K::Point_3> points;
  for (const auto& p : s.points) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polys;
  for (const auto& t : s.triangles) polys.push_back({t[0], t[1], t[2]});
  Mesh m;
  ok = PMP::is_polygon_soup_a_polygon_mesh(polys);
  if (ok) PMP::polygon_soup_to_polygon_mesh(points, polys, m);
  return m;
}

using Polyhedron = CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3>;

// val3dity's shell construction (validate_shell.cpp, ConstructShell): every point, then every
// face's triangles in order, each added to a halfedge structure if it fits. A triangle that does
// not fit is tried reversed: if that fits, it runs along an edge of an earlier triangle in the
// same direction (307), else it would make an edge shared by three faces or a vertex join two
// fans of faces (303). `tri_face` is each triangle's input face.
class ShellBuilder : public CGAL::Modifier_base<Polyhedron::HalfedgeDS> {
 public:
  ShellBuilder(const std::vector<Vec3>& pts, const std::vector<std::array<uint32_t, 3>>& tris,
               const std::vector<size_t>& tri_face, ErrorLog& log)
      : pts_(pts), tris_(tris), tri_face_(tri_face), log_(log) {}
  bool fitted = true;  // every triangle was added

  void operator()(Polyhedron::HalfedgeDS& hds) override {
    CGAL::Polyhedron_incremental_builder_3<Polyhedron::HalfedgeDS> b(hds, false);
    b.begin_surface(pts_.size(), tris_.size());
    for (const Vec3& p : pts_) b.add_vertex(K::Point_3(p.x, p.y, p.z));
    for (size_t t = 0; t < tris_.size(); ++t) {
      std::array<std::size_t, 3> f{tris_[t][0], tris_[t][1], tris_[t][2]};
      if (b.test_facet(f.begin(), f.end())) {
        b.add_facet(f.begin(), f.end())->facet()->id() = tri_face_[t];
        continue;
      }
      fitted = false;
      const std::string face = "face " + std::to_string(tri_face_[t]);
      std::swap(f[1], f[2]);
      if (b.test_facet(f.begin(), f.end()))
        log_.add(solid_code::kPolygonWrongOrientation,
                 face + " runs along an edge of another face in the same direction, near " + fmt(pts_[f[0]]));
      else
        log_.add(solid_code::kNonManifoldCase, face +
                                                   " would make an edge shared by more than two faces or a "
                                                   "vertex joining separate fans of faces, near " +
                                                   fmt(pts_[f[0]]));
    }
    if (fitted && b.check_unconnected_vertices()) b.remove_unconnected_vertices();
    b.end_surface();
  }

 private:
  const std::vector<Vec3>& pts_;
  const std::vector<std::array<uint32_t, 3>>& tris_;
  const std::vector<size_t>& tri_face_;
  ErrorLog& log_;
};

// The shell's topology as val3dity decides it (Surface::validate_as_shell), on the faces'
// triangles rather than their rings: a vertex of a face that its triangulation puts into one of
// the face's edges (a hole's corner on the outer ring's edge) splits that edge in the triangles
// only, and leaves the face across it without a partner. After a triangle that does not fit
// (303/307) nothing else is checked; then an open shell is one hole per border cycle (302) unless
// its faces fall apart (305).
void check_shell_topology(const std::vector<Vec3>& pts, const std::vector<std::array<uint32_t, 3>>& tris,
                          const std::vector<size_t>& tri_face, ErrorLog& log) {
  Polyhedron p;
  ShellBuilder build(pts, tris, tri_face, log);
  p.delegate(build);
  if (!build.fitted) return;
  if (!p.is_valid()) {
    log.add(solid_code::kNotValid2Manifold, "the faces' triangles do not form a valid halfedge structure");
    return;
  }
  const auto at = [](const Polyhedron::Vertex_handle v) {
    const K::Point_3& q = v->point();
    return Vec3{q.x(), q.y(), q.z()};
  };
  if (p.is_closed()) {
    if (const auto n = p.keep_largest_connected_components(1); n > 0)
      log.add(solid_code::kMultipleComponents, std::to_string(n + 1) + " separate groups of faces");
    return;
  }
  p.normalize_border();
  if (const auto n = p.keep_largest_connected_components(1); n > 0) {
    log.add(solid_code::kMultipleComponents, std::to_string(n + 1) + " separate groups of faces");
    return;
  }
  // One 302 per hole, each filled before the next is looked for (val3dity's loop).
  p.normalize_border();
  for (size_t guard = 0; p.size_of_border_edges() > 0 && guard < tris.size() + 1; ++guard) {
    const Polyhedron::Halfedge_handle h = std::next(p.border_halfedges_begin());
    log.add(solid_code::kShellNotClosed,
            "edge " + fmt(at(h->opposite()->vertex())) + "-" + fmt(at(h->vertex())) + " of face " +
                std::to_string(h->opposite()->facet()->id()) + " has no face across it");
    p.fill_hole(h);
    p.normalize_border();
  }
}

}  // namespace

std::vector<uint32_t> merge_vertices(const std::vector<Vec3>& v, double snap, std::vector<Vec3>& merged,
                                     bool strict) {
  const double cell = std::max(snap, 1e-12);
  std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
  auto key = [](int64_t x, int64_t y, int64_t z) {
    return (static_cast<uint64_t>(x) * 73856093u) ^ (static_cast<uint64_t>(y) * 19349663u) ^
           (static_cast<uint64_t>(z) * 83492791u);
  };
  // val3dity compares (dx² + dy²) + dz² with snap² (CGAL::squared_distance): the same operations.
  const double snap2 = snap * snap;
  auto close = [&](const Vec3& a, const Vec3& b) {
    if (!strict) return norm(a - b) <= snap;
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    return dx * dx + dy * dy + dz * dz < snap2;
  };
  std::vector<uint32_t> id(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    const int64_t cx = std::llround(v[i].x / cell), cy = std::llround(v[i].y / cell),
                  cz = std::llround(v[i].z / cell);
    // The earliest merged vertex that close, as val3dity scans its list of points in order.
    int64_t found = -1;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (uint32_t m : it->second)
            if ((found < 0 || m < found) && close(v[i], merged[m])) found = m;
        }
    if (found < 0) {
      found = static_cast<int64_t>(merged.size());
      merged.push_back(v[i]);
      grid[key(cx, cy, cz)].push_back(static_cast<uint32_t>(found));
    }
    id[i] = static_cast<uint32_t>(found);
  }
  return id;
}

const char* solid_error_name(int code) {
  switch (code) {
    case solid_code::kTooFewPoints:
      return "TOO_FEW_POINTS";
    case solid_code::kConsecutivePointsSame:
      return "CONSECUTIVE_POINTS_SAME";
    case solid_code::kRingSelfIntersection:
      return "RING_SELF_INTERSECTION";
    case solid_code::kRingCollapsed:
      return "RING_COLLAPSED";
    case solid_code::kIntersectionRings:
      return "INTERSECTION_RINGS";
    case solid_code::kNonPlanarPolygon:
      return "NON_PLANAR_POLYGON_DISTANCE_PLANE";
    case solid_code::kNonPlanarNormals:
      return "NON_PLANAR_POLYGON_NORMALS_DEVIATION";
    case solid_code::kInteriorDisconnected:
      return "POLYGON_INTERIOR_DISCONNECTED";
    case solid_code::kInnerRingOutside:
      return "INNER_RING_OUTSIDE";
    case solid_code::kInnerRingsNested:
      return "INNER_RINGS_NESTED";
    case solid_code::kOrientationRingsSame:
      return "ORIENTATION_RINGS_SAME";
    case solid_code::kNotValid2Manifold:
      return "NOT_VALID_2_MANIFOLD";
    case solid_code::kTooFewPolygons:
      return "TOO_FEW_POLYGONS";
    case solid_code::kShellNotClosed:
      return "SHELL_NOT_CLOSED";
    case solid_code::kNonManifoldCase:
      return "NON_MANIFOLD_CASE";
    case solid_code::kPolygonWrongOrientation:
      return "POLYGON_WRONG_ORIENTATION";
    case solid_code::kMultipleComponents:
      return "MULTIPLE_CONNECTED_COMPONENTS";
    case solid_code::kShellSelfIntersection:
      return "SHELL_SELF_INTERSECTION";
    case solid_code::kWrongOrientationShell:
      return "WRONG_ORIENTATION_SHELL";
    default:
      return "UNKNOWN";
  }
}

bool triangulate_polygon(const std::vector<std::vector<uint32_t>>& rings, const std::vector<Vec3>& pts,
                         std::vector<std::array<uint32_t, 3>>& out) {
  if (rings.empty() || rings[0].size() < 3) return false;
  const Vec3 n = newell(rings[0], pts);
  if (!(norm(n) > 0)) return false;
  ErrorLog log;
  const size_t before = out.size();
  triangulate_face(rings, pts, n, 0, log, out);
  if (!log.only({})) {
    out.resize(before);
    return false;
  }
  return out.size() > before;
}

namespace {

// An ear of the polygon (two ring edges and a chord) whose middle vertex lies within 1/100 of the
// chord's length from it is a sliver whose normal is rounding noise: a corner kept for a
// neighbouring part and rounded off its straight edge makes one, and a tall wall keeps it
// Delaunay. Its chord is flipped to the triangle behind it (in canonical order, so that a face
// two parts share gets the same flips), which ties the vertex to the far side of the face.
void flip_sliver_ears(CDT& cdt, const std::vector<Vec3>& pts) {
  for (int guard = 0; guard < 64; ++guard) {
    std::optional<std::pair<std::array<uint32_t, 3>, std::pair<CDT::Face_handle, int>>> best;
    for (auto fh : cdt.finite_face_handles()) {
      if (fh->info().nesting % 2 != 1) continue;
      for (int i = 0; i < 3; ++i) {
        if (cdt.is_constrained({fh, i}) || !cdt.is_constrained({fh, CDT::ccw(i)}) ||
            !cdt.is_constrained({fh, CDT::cw(i)}))
          continue;
        const CDT::Face_handle n = fh->neighbor(i);
        if (cdt.is_infinite(n) || n->info().nesting % 2 != 1) continue;
        const uint32_t a = fh->vertex(i)->info(), b = fh->vertex(CDT::ccw(i))->info(),
                       d = fh->vertex(CDT::cw(i))->info();
        const Vec3 chord = pts[d] - pts[b];
        const double len = norm(chord);
        const double height = norm(cross(pts[a] - pts[b], chord));  // a's distance from the chord, × len
        if (!(len > 0) || height / len > 1e-2 * len) continue;
        // The flip must keep both new triangles (a, b, w) and (a, w, d) turning like the face.
        const CDT::Vertex_handle w = n->vertex(n->index(fh));
        const auto& pa = fh->vertex(i)->point();
        if (CGAL::orientation(pa, fh->vertex(CDT::ccw(i))->point(), w->point()) != CGAL::LEFT_TURN ||
            CGAL::orientation(pa, w->point(), fh->vertex(CDT::cw(i))->point()) != CGAL::LEFT_TURN)
          continue;
        // Nor make an ear at least as thin across the new chord (a, w): in a thin quad of ring
        // edges both diagonals make an ear within 1/100, and flipping each in turn would go back
        // and forth. The thinner one is flipped, once.
        const uint32_t wi = w->info();
        const double ear = height / (len * len);
        const auto thinner_back = [&](uint32_t apex, CDT::Vertex_handle other) {
          const Vec3 back = pts[wi] - pts[a];
          const double l2 = dot(back, back);
          return cdt.is_constrained({n, n->index(other)}) && l2 > 0 &&
                 norm(cross(pts[apex] - pts[a], back)) / l2 <= ear;
        };
        if (thinner_back(d, fh->vertex(CDT::ccw(i))) || thinner_back(b, fh->vertex(CDT::cw(i)))) continue;
        std::array<uint32_t, 3> key{a, std::min(b, d), std::max(b, d)};
        if (!best || key < best->first) best = {{key, {fh, i}}};
      }
    }
    if (!best) return;
    CDT::Face_handle f = best->second.first;
    cdt.flip(f, best->second.second);
    for (auto fh : cdt.all_face_handles()) fh->info().nesting = -1;
    mark_domains(cdt);
  }
}

}  // namespace

bool triangulate_polygon_canonical(const std::vector<std::vector<uint32_t>>& rings,
                                   const std::vector<Vec3>& pts, std::vector<std::array<uint32_t, 3>>& out) {
  if (rings.empty() || rings[0].size() < 3) return false;
  const Vec3 n = newell(rings[0], pts);
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  if (!(ax + ay + az > 0)) return false;
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  std::vector<uint32_t> used;
  for (const auto& r : rings) used.insert(used.end(), r.begin(), r.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  CDT cdt;
  std::unordered_map<uint32_t, CDT::Vertex_handle> handle;
  try {
    for (uint32_t id : used) {
      CDT::Vertex_handle h = cdt.insert(K::Point_2(pts[id][u], pts[id][v]));
      h->info() = id;
      handle[id] = h;
    }
    for (const auto& ring : rings)
      for (size_t i = 0; i < ring.size(); ++i) {
        CDT::Vertex_handle a = handle[ring[i]], b = handle[ring[(i + 1) % ring.size()]];
        if (a != b) cdt.insert_constraint(a, b);
      }
  } catch (const CDT::Intersection_of_constraints_exception&) { return false; }
  if (cdt.number_of_vertices() != used.size()) return false;  // two points project onto one
  mark_domains(cdt);
  flip_sliver_ears(cdt, pts);
  // CCW in (u, v) is CCW about +axis; the ring turns about n, whose component on the axis has
  // the sign of n[drop].
  const bool flip = n[drop] < 0;
  const size_t before = out.size();
  for (auto fh : cdt.finite_face_handles()) {
    if (fh->info().nesting % 2 != 1) continue;
    const uint32_t a = fh->vertex(0)->info(), b = fh->vertex(1)->info(), c = fh->vertex(2)->info();
    out.push_back(flip ? std::array<uint32_t, 3>{a, c, b} : std::array<uint32_t, 3>{a, b, c});
  }
  return out.size() > before;
}

bool exactly_coplanar(const std::vector<Vec3>& pts) {
  if (pts.size() <= 3) return true;
  std::vector<K::Point_3> p;
  for (const auto& q : pts) p.emplace_back(q.x, q.y, q.z);
  size_t j = 1;
  while (j < p.size() && p[j] == p[0]) ++j;
  size_t k = j + 1;
  while (k < p.size() && CGAL::collinear(p[0], p[j], p[k])) ++k;
  if (k >= p.size()) return true;  // all on one line
  for (size_t i = 0; i < p.size(); ++i)
    if (CGAL::orientation(p[0], p[j], p[k], p[i]) != CGAL::COPLANAR) return false;
  return true;
}

namespace {

// val3dity's rules for a face with holes, which it leaves to GEOS (IsValidOp on the rings
// projected onto the face's plane), with exact predicates on the same projection: rings crossing
// or running along each other (201), a hole outside the outer ring (206), a hole inside another
// (207), holes touching the outer ring or each other so that they cut the face in two (205, e.g.
// a hole touching the outer ring at two vertices). Rings may touch at single points. 0 = valid.
int polygon_rings_rule(const std::vector<CGAL::Polygon_2<K>>& rings) {
  using P2 = K::Point_2;
  using S2 = K::Segment_2;
  // Touch points: a point where two rings meet, and the rings meeting there.
  std::map<P2, std::set<size_t>> touches;
  for (size_t i = 0; i < rings.size(); ++i)
    for (size_t j = i + 1; j < rings.size(); ++j)
      for (auto a = rings[i].edges_begin(); a != rings[i].edges_end(); ++a)
        for (auto b = rings[j].edges_begin(); b != rings[j].edges_end(); ++b) {
          const S2 &sa = *a, &sb = *b;
          if (!CGAL::do_intersect(sa, sb)) continue;
          const auto on = [](const S2& s, const P2& q) { return s.has_on(q); };
          std::vector<P2> at;  // the endpoints where they meet
          for (const P2& q : {sa.source(), sa.target()})
            if (on(sb, q)) at.push_back(q);
          for (const P2& q : {sb.source(), sb.target()})
            if (on(sa, q)) at.push_back(q);
          if (at.empty()) return solid_code::kIntersectionRings;  // a proper crossing
          std::sort(at.begin(), at.end());
          at.erase(std::unique(at.begin(), at.end()), at.end());
          if (at.size() > 1) return solid_code::kIntersectionRings;  // along each other
          touches[at[0]].insert(i), touches[at[0]].insert(j);
        }
  // A point of ring `r` off ring `boundary`'s boundary (the first one; every point of a ring that
  // only touches the other lies on one side of it).
  const auto inside = [&](size_t r, size_t boundary) {
    for (auto v = rings[r].vertices_begin(); v != rings[r].vertices_end(); ++v) {
      const CGAL::Bounded_side side = rings[boundary].bounded_side(*v);
      if (side != CGAL::ON_BOUNDARY) return side == CGAL::ON_BOUNDED_SIDE;
    }
    return true;  // on it all along (not reached after the tests above)
  };
  for (size_t h = 1; h < rings.size(); ++h)
    if (!inside(h, 0)) return solid_code::kInnerRingOutside;
  for (size_t h = 1; h < rings.size(); ++h)
    for (size_t g = 1; g < rings.size(); ++g)
      if (g != h && inside(h, g)) return solid_code::kInnerRingsNested;
  // Rings and touch points as a graph: a cycle encloses part of the face.
  UnionFind graph(static_cast<uint32_t>(rings.size() + touches.size()));
  uint32_t node = static_cast<uint32_t>(rings.size());
  for (const auto& [point, at] : touches) {
    for (size_t r : at) {
      if (graph.find(static_cast<uint32_t>(r)) == graph.find(node)) return solid_code::kInteriorDisconnected;
      graph.link(static_cast<uint32_t>(r), node);
    }
    ++node;
  }
  return 0;
}

// The checks, on vertices already merged (`id`: each input vertex's merged index into `pts`).
// Rings (1xx), as val3dity reads them: merged ids; fewer than 3 points (101), else a vertex
// repeated consecutively (102; CityJSON rings are not closed explicitly, so a first vertex
// repeated at the end counts). False when the face is gone.
bool merged_rings(const PolygonMesh& solid, size_t fi, const std::vector<uint32_t>& id, ErrorLog& log,
                  SolidCheck& out, std::vector<std::vector<uint32_t>>& rings) {
  bool face_ok = true;
  for (size_t r = 0; r < solid.faces[fi].rings.size(); ++r) {
    const auto& in = solid.faces[fi].rings[r];
    const std::string where = "face " + std::to_string(fi) + ", ring " + std::to_string(r);
    std::vector<uint32_t> ring;
    for (uint32_t v : in) {
      if (v >= id.size()) {
        face_ok = false;
        continue;
      }
      ring.push_back(id[v]);
    }
    if (ring.size() < 3) {
      log.add(solid_code::kTooFewPoints, where + " has " + std::to_string(ring.size()) + " points");
      out.bad_faces.emplace_back(fi, solid_code::kTooFewPoints);
      face_ok = false;
      continue;
    }
    bool repeats = false;
    for (size_t i = 0; i < ring.size(); ++i) repeats = repeats || ring[i] == ring[(i + 1) % ring.size()];
    if (repeats) {
      log.add(solid_code::kConsecutivePointsSame, where + " repeats a vertex consecutively");
      out.bad_faces.emplace_back(fi, solid_code::kConsecutivePointsSame);
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    }
    if (ring.size() < 3) {
      // Only the repeat is val3dity's error; the ring is gone all the same.
      out.bad_faces.emplace_back(fi, solid_code::kTooFewPoints);
      face_ok = false;
      continue;
    }
    rings.push_back(std::move(ring));
  }
  return face_ok && !rings.empty();
}

// Polygon rules (2xx) of one face's merged rings, val3dity's triangles of it (`face_tris`, empty:
// ours) and its Newell vector `n`. False when the face cannot go into the shell.
bool face_rules(size_t fi, const std::vector<std::vector<uint32_t>>& rings, const std::vector<Vec3>& p3,
                const SolidTolerances& tol, ErrorLog& log, SolidCheck& out,
                std::vector<std::array<uint32_t, 3>>& face_tris, Vec3& n_out) {
  // Polygon (2xx): planarity against the least-squares plane of all its points.
  std::vector<Vec3> fp;
  for (const auto& ring : rings)
    for (uint32_t v : ring) fp.push_back(p3[v]);
  Vec3 c;
  for (const auto& p : fp) c += p;
  c = c / static_cast<double>(fp.size());
  std::vector<Vec3> centred;
  for (const auto& p : fp) centred.push_back(p - c);  // fit in local coordinates (precision)
  const Plane pl = fit_plane(centred);
  double worst = 0;
  for (const auto& p : centred) worst = std::max(worst, std::abs(pl.signed_distance(p)));
  const bool planar = worst <= tol.planarity || fp.size() == 3;
  const std::string where = "face " + std::to_string(fi);
  auto off_plane = [&] {  // only for a face that is not planar: formatting is most of a face's check
    return where + ": a point lies " + fmt(worst) + " m from the face's plane (tolerance " +
           fmt(tol.planarity) + " m)";
  };
  if (tol.normals_deg > 0) {
    // val3dity's polygon rules, in coordinates local to the face (city coordinates are large).
    const Vec3 o = p3[rings[0][0]];
    std::vector<K::Point_3> local(p3.size());
    for (const auto& ring : rings)
      for (uint32_t v : ring) local[v] = K::Point_3(p3[v].x - o.x, p3[v].y - o.y, p3[v].z - o.z);
    if (rings.size() == 1 && rings[0].size() == 3 &&
        CGAL::collinear(local[rings[0][0]], local[rings[0][1]], local[rings[0][2]])) {
      log.add(solid_code::kRingSelfIntersection, where + ": a triangle collapsed to a line");
      out.bad_faces.emplace_back(fi, solid_code::kRingSelfIntersection);
      return false;
    }
    // val3dity tests the distance to the plane first and says no more about a face beyond it.
    const std::vector<CGAL::Polygon_2<K>> projected = projected_rings(rings, local);
    if (!rings_simple(projected)) {
      if (planar) {
        log.add(solid_code::kRingSelfIntersection,
                where + ": a ring touches or crosses itself, or has no area, in the face's plane");
      } else {
        log.add(solid_code::kNonPlanarPolygon, off_plane());
      }
      out.bad_faces.emplace_back(fi, solid_code::kRingSelfIntersection);
      return false;
    }
    if (planar && rings.size() > 1) {
      if (const int code = polygon_rings_rule(projected)) {
        const char* what = code == solid_code::kIntersectionRings  ? "its rings cross or run along each other"
                           : code == solid_code::kInnerRingOutside ? "a hole lies outside the outer ring"
                           : code == solid_code::kInnerRingsNested ? "a hole lies inside another hole"
                                                                   : "its holes cut the face in two";
        log.add(code, where + ": " + what + " in the face's plane");
        out.bad_faces.emplace_back(fi, code);
        if (code == solid_code::kIntersectionRings) return false;
      }
    }
    if (!val3dity_triangles(rings, local, face_tris)) face_tris.clear();
    const double dev = face_tris.empty() ? -1 : triangle_normals_deviation_deg(face_tris, local);
    if (dev > tol.normals_deg) {
      log.add(solid_code::kNonPlanarNormals, where + ": its triangles' normals differ by " + fmt(dev) +
                                                 " degrees (tolerance " + fmt(tol.normals_deg) + ")");
      out.bad_faces.emplace_back(fi, solid_code::kNonPlanarNormals);
    }
  }
  const Vec3 n = newell(rings[0], p3);
  if (norm(n) <= 1e-12) {
    // No area: a bow-tie (its halves cancel) or a collapsed ring.
    bool crosses = false;
    for (const auto& ring : rings) {
      CDT cdt;
      try {
        insert_ring(cdt, ring, p3, frame_for(p3[ring[0]], pl.n));
      } catch (const CDT::Intersection_of_constraints_exception&) { crosses = true; }
    }
    if (crosses) log.add(solid_code::kRingSelfIntersection, where + ": a ring crosses itself");
    else log.add(solid_code::kRingCollapsed, where + ": the outer ring has no area");
    out.bad_faces.emplace_back(fi, crosses ? solid_code::kRingSelfIntersection : solid_code::kRingCollapsed);
    return false;
  }
  if (!planar) {
    out.bad_faces.emplace_back(fi, solid_code::kNonPlanarPolygon);
    log.add(solid_code::kNonPlanarPolygon, off_plane());
  }
  n_out = n;
  return true;
}

// The faces' triangles as val3dity builds them into a shell (3xx topology).
void build_shell(const std::vector<std::vector<std::vector<uint32_t>>>& faces,
                 const std::vector<size_t>& face_index, const std::vector<Vec3>& normals,
                 const std::vector<std::vector<std::array<uint32_t, 3>>>& val3dity_tris, ErrorLog& log,
                 SolidCheck& out) {
  const std::vector<Vec3>& p3 = out.shell.points;
  // Shell (3xx): the faces' triangles as val3dity builds them into a shell, then volume and
  // intersections.
  if (faces.size() < 4)
    log.add(solid_code::kTooFewPolygons, std::to_string(faces.size()) + " valid faces (at least 4 needed)");
  std::vector<size_t> tri_face;
  for (size_t fi = 0; fi < faces.size(); ++fi) {
    const size_t before = out.shell.triangles.size();
    triangulate_face(faces[fi], p3, normals[fi], face_index[fi], log, out.shell.triangles);
    if (!val3dity_tris[fi].empty()) {
      out.shell.triangles.resize(before);
      out.shell.triangles.insert(out.shell.triangles.end(), val3dity_tris[fi].begin(),
                                 val3dity_tris[fi].end());
    }
    tri_face.resize(out.shell.triangles.size(), face_index[fi]);
  }
  if (faces.size() >= 4) check_shell_topology(p3, out.shell.triangles, tri_face, log);
}

// A topologically closed shell: its volume, convexity, self-intersections (306) and
// orientation (405).
void shell_geometry(ErrorLog& log, SolidCheck& out) {
  const std::vector<Vec3>& p3 = out.shell.points;
  const Vec3 o = out.box.center();
  double six_v = 0;
  for (const auto& t : out.shell.triangles) six_v += dot(p3[t[0]] - o, cross(p3[t[1]] - o, p3[t[2]] - o));
  out.volume = six_v / 6;
  if (out.hull_volume > 0) out.convexity = std::min(1.0, std::max(0.0, out.volume / out.hull_volume));

  bool mesh_ok = false;
  const Mesh m = to_mesh(out.shell, mesh_ok);
  if (!mesh_ok) {
    log.add(solid_code::kShellSelfIntersection,
            "the triangulated faces do not form a 2-manifold surface (faces overlap in their plane)");
  } else {
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    PMP::self_intersections(m, std::back_inserter(pairs));
    if (!pairs.empty()) {
      const auto tri = [&](Mesh::Face_index f) {
        Vec3 c;
        for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
          const auto& p = m.point(v);
          c += Vec3{p.x(), p.y(), p.z()} / 3.0;
        }
        return fmt(c);
      };
      log.add(solid_code::kShellSelfIntersection, std::to_string(pairs.size()) +
                                                      " pairs of triangles intersect, e.g. near " +
                                                      tri(pairs[0].first) + " and " + tri(pairs[0].second));
    }
  }
  // The Solid's orientation, checked by val3dity once its shell is valid (405).
  if (!log.has(solid_code::kShellSelfIntersection) && !(out.volume > 0))
    log.add(solid_code::kWrongOrientationShell,
            "the faces point inwards (signed volume " + fmt(out.volume) + " m³)");
  out.closed_manifold =
      !log.has(solid_code::kShellSelfIntersection) && !log.has(solid_code::kWrongOrientationShell);
}

SolidCheck check_merged(const PolygonMesh& solid, const std::vector<uint32_t>& id, std::vector<Vec3> pts,
                        const SolidTolerances& tol, bool measures) {
  SolidCheck out;
  ErrorLog log;
  out.shell.points = std::move(pts);
  const std::vector<Vec3>& p3 = out.shell.points;
  for (const auto& p : p3) out.box.add(p);

  std::vector<std::vector<std::vector<uint32_t>>> faces;
  std::vector<size_t> face_index;  // input face of each entry of `faces`
  std::vector<Vec3> normals;
  // With val3dity's face rules: each face's triangles as val3dity makes them (empty: ours).
  std::vector<std::vector<std::array<uint32_t, 3>>> val3dity_tris;
  std::vector<std::array<uint32_t, 3>> face_tris;
  for (size_t fi = 0; fi < solid.faces.size(); ++fi) {
    std::vector<std::vector<uint32_t>> rings;
    face_tris.clear();
    if (!merged_rings(solid, fi, id, log, out, rings)) continue;
    Vec3 n;
    if (!face_rules(fi, rings, p3, tol, log, out, face_tris, n)) continue;
    out.area += norm(n) / 2;
    faces.push_back(std::move(rings));
    face_index.push_back(fi);
    normals.push_back(n);
    val3dity_tris.push_back(face_tris);
  }
  for (size_t fi = 0; fi < faces.size(); ++fi)
    for (size_t r = 1; r < faces[fi].size(); ++r) out.area -= norm(newell(faces[fi][r], p3)) / 2;
  build_shell(faces, face_index, normals, val3dity_tris, log, out);

  // Non-planarity within reason does not stop the shell checks (the faces are triangulated).
  const bool topology_ok = log.only({solid_code::kNonPlanarPolygon, solid_code::kNonPlanarNormals});
  // Hull and convexity are measures, wanted whatever the validity.
  if (measures) {
    const Hull hull = convex_hull(p3);
    out.hull_volume = hull.volume;
    out.hull_facets = hull.facets;
  }
  if (topology_ok) shell_geometry(log, out);
  out.errors = log.take();
  return out;
}

}  // namespace

SolidCheck check_solid(const PolygonMesh& solid, const SolidTolerances& tol, bool measures) {
  std::vector<Vec3> pts;
  const std::vector<uint32_t> id = merge_vertices(solid.vertices, tol.snap, pts, tol.snap_strict);
  SolidCheck out = check_merged(solid, id, std::move(pts), tol, measures);
  if (tol.snap_apart > 0 && out.valid()) {
    // The same solid with the vertices merged only up to `snap_apart`: where that keeps some
    // apart, it must be valid that way too.
    std::vector<Vec3> apart_pts;
    const std::vector<uint32_t> apart = merge_vertices(solid.vertices, tol.snap_apart, apart_pts);
    if (apart != id) {
      SolidTolerances t = tol;
      t.snap = tol.snap_apart;
      const SolidCheck other = check_merged(solid, apart, std::move(apart_pts), t, false);
      for (const SolidError& e : other.errors)
        out.errors.push_back({e.code, e.name,
                              e.message + " (with the vertices " + fmt(tol.snap_apart) + " m to " +
                                  fmt(tol.snap) + " m apart not merged, as val3dity may not merge them)"});
      out.bad_faces.insert(out.bad_faces.end(), other.bad_faces.begin(), other.bad_faces.end());
      if (!other.valid()) out.closed_manifold = false;
    }
  }
  return out;
}

namespace {

// Adds the faces of `m` that bound the common part: those inside `other`, and (when
// `take_shared`) those lying on `other`'s surface with both solids behind them.
void add_common_faces(const Mesh& m, const Mesh& other, bool take_shared, const Vec3& o, double& six_v,
                      double& area) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  const Tree tree(faces(other).first, faces(other).second, other);
  const CGAL::Side_of_triangle_mesh<Mesh, K> side(other);
  constexpr double kOn = 1e-6;  // m: on the other surface (corefined, so exactly up to rounding)
  for (auto f : m.faces()) {
    std::array<Vec3, 3> p;
    int i = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      const auto& q = m.point(v);
      if (i < 3) p[i] = {q.x(), q.y(), q.z()};
      ++i;
    }
    const Vec3 c = (p[0] + p[1] + p[2]) / 3.0, n = cross(p[1] - p[0], p[2] - p[0]);
    if (norm(n) == 0) continue;
    const double d = std::sqrt(tree.squared_distance(K::Point_3(c.x, c.y, c.z)));
    if (d < kOn) {
      if (!take_shared) continue;
      const Vec3 probe = c - normalized(n) * (10 * kOn);  // just behind the face, inside m
      if (side(K::Point_3(probe.x, probe.y, probe.z)) != CGAL::ON_BOUNDED_SIDE) continue;
    } else if (side(K::Point_3(c.x, c.y, c.z)) != CGAL::ON_BOUNDED_SIDE) {
      continue;
    }
    six_v += dot(p[0] - o, cross(p[1] - o, p[2] - o));
    area += norm(n) / 2;
  }
}

}  // namespace

// Volume inside both meshes, estimated on a regular grid of cell centres (at most `budget`
// points) over the intersection of their bounding boxes; exact side-of-mesh predicates.
double sampled_common_volume(const Mesh& ma, const Mesh& mb, size_t budget) {
  const auto ba = CGAL::Polygon_mesh_processing::bbox(ma), bb = CGAL::Polygon_mesh_processing::bbox(mb);
  double lo[3], hi[3], ext[3], box_volume = 1;
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::max(ba.min(i), bb.min(i));
    hi[i] = std::min(ba.max(i), bb.max(i));
    ext[i] = hi[i] - lo[i];
    if (!(ext[i] > 0)) return 0;
    box_volume *= ext[i];
  }
  const double step = std::cbrt(box_volume / static_cast<double>(budget));
  size_t n[3];
  for (int i = 0; i < 3; ++i) n[i] = std::max<size_t>(1, static_cast<size_t>(std::ceil(ext[i] / step)));
  const CGAL::Side_of_triangle_mesh<Mesh, K> side_a(ma), side_b(mb);
  size_t both = 0;
  for (size_t i = 0; i < n[0]; ++i)
    for (size_t j = 0; j < n[1]; ++j)
      for (size_t k = 0; k < n[2]; ++k) {
        const K::Point_3 p(lo[0] + ext[0] * (i + 0.5) / n[0], lo[1] + ext[1] * (j + 0.5) / n[1],
                           lo[2] + ext[2] * (k + 0.5) / n[2]);
        both += side_a(p) == CGAL::ON_BOUNDED_SIDE && side_b(p) == CGAL::ON_BOUNDED_SIDE;
      }
  return box_volume * static_cast<double>(both) / static_cast<double>(n[0] * n[1] * n[2]);
}

std::optional<Common> common_volume_by_faces(const TriangleShell& a, const TriangleShell& b) {
  bool ok_a = false, ok_b = false;
  Mesh ma = to_mesh(a, ok_a), mb = to_mesh(b, ok_b);
  if (!ok_a || !ok_b) return std::nullopt;
  const Mesh ma0 = ma, mb0 = mb;  // before corefinement, for the sampling fallback
  try {
    PMP::corefine(ma, mb);
  } catch (const std::exception&) { return std::nullopt; }
  // The divergence theorem needs the picked faces to close up. When near-coplanar contacts make
  // the inside/on classification of some faces unreliable they do not, and the sum then depends
  // on the origin (a 3D BAG pair read 0.97 m³ from one origin and 1.90 m³ from another, while
  // sampling finds ~1e-4 m³): evaluate at two origins and fall back to sampling when they differ.
  const Vec3 o = a.points.empty() ? Vec3{} : a.points[0];
  BBox box;
  for (const Vec3& p : a.points) box.add(p);
  const Vec3 o2 = o + Vec3{1, 2, 3} * std::max(box.diagonal(), 1.0);
  double six_v = 0, area = 0, six_v2 = 0, area2 = 0;
  add_common_faces(ma, mb, true, o, six_v, area);
  add_common_faces(mb, ma, false, o, six_v, area);
  add_common_faces(ma, mb, true, o2, six_v2, area2);
  add_common_faces(mb, ma, false, o2, six_v2, area2);
  const double v = std::abs(six_v) / 6, v2 = std::abs(six_v2) / 6;
  if (std::abs(v - v2) <= 1e-6 * std::max(1.0, v)) return Common{v, area};
  return Common{sampled_common_volume(ma0, mb0, 200000), area};
}

std::optional<Common> common_volume(const TriangleShell& a, const TriangleShell& b) {
  bool ok_a = false, ok_b = false;
  Mesh ma = to_mesh(a, ok_a), mb = to_mesh(b, ok_b), common;
  if (!ok_a || !ok_b) return std::nullopt;
  try {
    // false when the common part is not a 2-manifold (e.g. two pieces meeting at an edge).
    if (PMP::corefine_and_compute_intersection(ma, mb, common))
      return common.is_empty() ? Common{} : Common{std::abs(PMP::volume(common)), PMP::area(common)};
  } catch (const std::exception&) {}
  return common_volume_by_faces(a, b);
}

namespace {

// Is every point of `b` on or beyond the plane of a facet of `a`'s convex hull? Exact predicates
// on the hull's own vertices: then the interiors cannot meet.
bool hull_facet_separates(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return facet_separates(hull_facets(a), b);
}

}  // namespace

bool min_distance_beyond(const TriangleShell& a, const TriangleShell& b, double d) {
  std::vector<Vec3> mine = b.points;
  std::sort(mine.begin(), mine.end(),
            [](const Vec3& u, const Vec3& v) { return std::tie(u.x, u.y, u.z) < std::tie(v.x, v.y, v.z); });
  const double d2 = d * d;
  // A point farther than d from a triangle's box along an axis is farther than d from the
  // triangle: only the triangles whose box, grown by a little more than d (for the rounding of
  // the closest point), holds the point are measured. The answer is the full scan's.
  // Likewise a point farther than d from a triangle's plane, for a triangle whose normal is well
  // conditioned (twice its area at least 1e-6 of its longest edge squared: no thinner than a
  // millionth of its length), so that the plane's distance is off by far less than the margin.
  std::vector<BBox> boxes(b.triangles.size());
  std::vector<Plane> planes(b.triangles.size(), Plane{{0, 0, 0}, 0});
  BBox all;
  for (size_t i = 0; i < b.triangles.size(); ++i) {
    const auto& t = b.triangles[i];
    for (const uint32_t v : t) boxes[i].add(b.points[v]);
    all.add(boxes[i].lo);
    all.add(boxes[i].hi);
    const Vec3 &p0 = b.points[t[0]], &p1 = b.points[t[1]], &p2 = b.points[t[2]];
    const Vec3 n = cross(p1 - p0, p2 - p0);
    const double longest = std::max({norm(p1 - p0), norm(p2 - p0), norm(p2 - p1)});
    if (norm(n) >= 1e-6 * longest * longest && norm(n) > 0) planes[i] = {n / norm(n), -dot(n / norm(n), p0)};
  }
  if (!all.valid()) return true;
  const double reach = 1.001 * d + 1e-12 * (1 + std::abs(all.lo.x) + std::abs(all.lo.y) + std::abs(all.lo.z) +
                                            std::abs(all.hi.x) + std::abs(all.hi.y) + std::abs(all.hi.z));
  auto within = [reach](const BBox& box, const Vec3& p) {
    for (int k = 0; k < 3; ++k)
      if (p[k] < box.lo[k] - reach || p[k] > box.hi[k] + reach) return false;
    return true;
  };
  for (const Vec3& p : a.points) {
    if (!within(all, p)) continue;
    if (std::binary_search(mine.begin(), mine.end(), p, [](const Vec3& u, const Vec3& v) {
          return std::tie(u.x, u.y, u.z) < std::tie(v.x, v.y, v.z);
        }))
      continue;  // a vertex of both: on the common surface
    for (size_t i = 0; i < b.triangles.size(); ++i) {
      if (!within(boxes[i], p)) continue;
      if (planes[i].n != Vec3{0, 0, 0} && std::abs(planes[i].signed_distance(p)) > reach) continue;
      const auto& t = b.triangles[i];
      const Vec3 q = p - closest_on_triangle(p, b.points[t[0]], b.points[t[1]], b.points[t[2]]);
      if (dot(q, q) <= d2) return false;
    }
  }
  return true;
}

bool plane_separates(const Vec3& p, const Vec3& q, const Vec3& r, const std::vector<Vec3>& a,
                     const std::vector<Vec3>& b) {
  const K::Point_3 t0(p.x, p.y, p.z), t1(q.x, q.y, q.z), t2(r.x, r.y, r.z);
  if (CGAL::collinear(t0, t1, t2)) return false;
  auto side_of = [&](const std::vector<Vec3>& pts, CGAL::Orientation not_allowed) {
    return std::none_of(pts.begin(), pts.end(), [&](const Vec3& v) {
      return CGAL::orientation(t0, t1, t2, K::Point_3(v.x, v.y, v.z)) == not_allowed;
    });
  };
  return (side_of(a, CGAL::POSITIVE) && side_of(b, CGAL::NEGATIVE)) ||
         (side_of(a, CGAL::NEGATIVE) && side_of(b, CGAL::POSITIVE));
}

bool interiors_overlap(const TriangleShell& a, const TriangleShell& b, size_t* exact_tests) {
  BBox ba, bb;
  for (const Vec3& p : a.points) ba.add(p);
  for (const Vec3& p : b.points) bb.add(p);
  for (int axis = 0; axis < 3; ++axis)
    if (ba.hi[axis] <= bb.lo[axis] || bb.hi[axis] <= ba.lo[axis]) return false;  // at most touching
  if (hull_facet_separates(a.points, b.points) || hull_facet_separates(b.points, a.points)) return false;
  if (exact_tests) ++*exact_tests;
  return interiors_overlap_exact(a, b);
}

std::vector<std::array<Vec3, 3>> hull_facets(const std::vector<Vec3>& points) {
  std::vector<K::Point_3> pa;
  for (const Vec3& p : points) pa.emplace_back(p.x, p.y, p.z);
  Mesh hull;
  CGAL::convex_hull_3(pa.begin(), pa.end(), hull);
  std::vector<std::array<Vec3, 3>> out;
  for (auto f : hull.faces()) {
    std::array<Vec3, 3> t;
    int i = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull))
      if (i < 3) {
        const K::Point_3& q = hull.point(v);
        t[i++] = {q.x(), q.y(), q.z()};
      }
    out.push_back(t);
  }
  return out;
}

bool facet_separates(const std::vector<std::array<Vec3, 3>>& facets, const std::vector<Vec3>& other) {
  std::vector<K::Point_3> pb;
  for (const Vec3& p : other) pb.emplace_back(p.x, p.y, p.z);
  for (const auto& f : facets) {
    const K::Point_3 t0(f[0].x, f[0].y, f[0].z), t1(f[1].x, f[1].y, f[1].z), t2(f[2].x, f[2].y, f[2].z);
    if (std::all_of(pb.begin(), pb.end(),
                    [&](const K::Point_3& q) { return CGAL::orientation(t0, t1, t2, q) != CGAL::NEGATIVE; }))
      return true;
  }
  return false;
}

bool interiors_overlap_exact(const TriangleShell& a, const TriangleShell& b) {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  using EMesh = CGAL::Surface_mesh<EK::Point_3>;
  const auto exact_mesh = [](const TriangleShell& s) {
    std::vector<EK::Point_3> points;
    for (const auto& p : s.points) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::vector<std::size_t>> polys;
    for (const auto& t : s.triangles) polys.push_back({t[0], t[1], t[2]});
    EMesh m;
    PMP::polygon_soup_to_polygon_mesh(points, polys, m);
    return m;
  };
  EMesh ma = exact_mesh(a), mb = exact_mesh(b);
  // The common part by corefinement with exact constructions: the interiors meet when it has volume.
  try {
    EMesh common;
    EMesh ca = ma, cb = mb;
    if (PMP::corefine_and_compute_intersection(ca, cb, common))
      return !common.is_empty() && PMP::volume(common) > 0;
  } catch (const std::exception&) {}
  // A common part that is not a 2-manifold (two pieces meeting at an edge): val3dity's own test,
  // Nef polyhedra.
  using Nef = CGAL::Nef_polyhedron_3<EK>;
  const Nef na(ma), nb(mb);
  return !(na.interior() * nb.interior()).is_empty();
}

}  // namespace mc
