#include "core/preprocess.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <cmath>
#include <exception>
#include <stdexcept>

#include <tbb/parallel_invoke.h>
#include <tbb/task_group.h>

#include "core/carve.hpp"
#include "core/corner_snap.hpp"
#include "core/hausdorff.hpp"
#include "core/hole_planes.hpp"
#include "core/open_input.hpp"
#include "core/oracle.hpp"
#include "core/segmentation.hpp"
#include "core/solid_validation.hpp"
#include "core/soup.hpp"
#include "core/surface.hpp"
#include "core/surface_index.hpp"
#include "core/up_axis.hpp"
#include "core/thread_tag.hpp"

namespace mc {

Vec3 Preprocessed::to_input(const Vec3& p) const { return from_z_up(p + offset, up_axis); }

namespace {
// The volume agreement open models are held to (docs/algorithm.md §6.5; the open variants' 2 %).
constexpr double kOpenRelabel = 0.02;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Joins a task group when the scope ends, also on a throw: then its tasks not yet started are
// cancelled, and its own exception is dropped (the one in flight is the error).
struct WaitOnExit {
  tbb::task_group& group;
  ~WaitOnExit() {
    if (std::uncaught_exceptions() > 0) group.cancel();
    try {
      group.wait();
    } catch (...) {}
  }
};
}  // namespace

struct FidelityInputs {
  TriangleSoup input, cell;  // the input's triangles and the cell's boundary, centred frame
  double step = 0;           // sampling step
};

void measure_fidelity(Preprocessed& pre) {
  if (!pre.pending_fidelity) return;
  const FidelityInputs& f = *pre.pending_fidelity;
  const HausdorffResult h = hausdorff(f.input, f.cell, f.step);
  pre.hausdorff = h.symmetric;
  pre.hausdorff_in_to_cell = h.a_to_b;
  pre.hausdorff_cell_to_in = h.b_to_a;
  pre.mean_distance = h.mean_a_to_b;
  pre.mean_distance_cell_to_in = h.mean_b_to_a;
  pre.mean_distance_symmetric = h.mean_symmetric;
  pre.pending_fidelity.reset();
}

Preprocessed preprocess(const PolygonMesh& input, const PreprocessParams& p, Clock::time_point deadline,
                        double terrain_z, bool defer_fidelity) {
  const auto t0 = Clock::now();
  Preprocessed out;
  out.input_faces = input.faces.size();
  if (input.faces.empty()) throw std::runtime_error("empty geometry: no faces");

  // Frame: rotate to z-up, centre on the bounding box (all thresholds are then scale-relative).
  PolygonMesh mesh = input;
  // "auto" detects the up axis from the faces' orientations (the paper's y-up NYC crops), except
  // for inputs with semantic surfaces (city models: z-up by definition). A model without walls
  // (roofs and ground only: all faces are "walls" about y too) was taken as y-up.
  bool semantic = false;
  for (const Polygon& f : mesh.faces) semantic |= f.semantic >= 0;
  out.up_axis = p.up_axis == "y" ? 1 : (p.up_axis == "z" || semantic ? 2 : detect_up_axis(mesh));
  if (out.up_axis != 2) to_z_up(mesh, out.up_axis);
  BBox raw;
  for (const Polygon& f : mesh.faces)
    for (const auto& r : f.rings)
      for (uint32_t v : r)
        if (v < mesh.vertices.size() && is_finite(mesh.vertices[v])) raw.add(mesh.vertices[v]);
  if (!raw.valid()) throw std::runtime_error("degenerate geometry: no finite vertex");
  const double diag0 = raw.diagonal();
  if (!(diag0 > 0)) throw std::runtime_error("degenerate geometry: zero extent");
  out.cell_size = p.cell_size > 0 ? p.cell_size : p.f_d * diag0;
  out.dist = p.dist_thresh > 0 ? p.dist_thresh : out.cell_size / 4;
  out.angle_rad = p.angle_thresh_deg * M_PI / 180.0;
  out.hair = std::max(0.1 * out.dist, p.output_grid);
  // The oracle decides parity per closed shell, and which shells are closed is topology: it
  // sees the input welded only where positions coincide (1e-9 of the diagonal). The weld of
  // the other stages (δ/10, at most 1e-6 of the diagonal) can join float-neighbour vertices of
  // stacked storeys into shells that no longer split into closed patches (sample18 lost two
  // storeys to plain parity).
  // (the two cleanings read the same mesh and are independent: one task each)
  PolygonMesh oracle_mesh, cleaned;
  tbb::parallel_invoke(with_thread_tag([&] { oracle_mesh = clean_soup(mesh, diag0 * 1e-9, nullptr); }),
                       with_thread_tag([&] {
                         cleaned = clean_soup(mesh, std::min(out.dist * 0.1, diag0 * 1e-6), &out.problems);
                       }));
  mesh = std::move(cleaned);
  if (mesh.faces.empty()) throw std::runtime_error("degenerate geometry: no valid face after cleaning");
  out.offset = bbox_center(mesh);
  translate(mesh, -out.offset);
  translate(oracle_mesh, -out.offset);
  for (const Vec3& v : mesh.vertices) out.box.add(v);
  out.labels = mesh.semantic_labels;
  // Open inputs (missing walls, grounds, roofs, §6.4), known before the planes: the vertical
  // planes of their open boundary come after the hole planes, so that a missing wall is closed
  // where its roof or ground ends.
  const OpenInput open = analyse_open_input(mesh, out.dist);
  out.open_input = open.open(out.cell_size);

  // The fast path's validity check (docs/algorithm.md §6.6) reads only the oracle's mesh, so it
  // runs beside the planes and the oracle's build; the decision waits for it before the carving.
  const TriangleSoup oracle_tris = triangulate(oracle_mesh);
  const bool check_fast_path = p.fast_path && !out.open_input && !oracle_tris.triangles.empty();
  SolidCheck check;
  tbb::task_group checking;
  const WaitOnExit join_checking{checking};  // (a throw below must not leave the task running)
  if (check_fast_path) {
    checking.run(with_thread_tag([&] {
      SolidTolerances tol;
      tol.snap = diag0 * 1e-9;  // the oracle's weld: its topology is the one checked
      check = check_solid(oracle_mesh, tol, false);
    }));
  }

  // Planes.
  PreprocessParams resolved = p;
  resolved.cell_size = out.cell_size;
  resolved.dist_thresh = out.dist;
  const SegmentationParams sp = segmentation_params(resolved);
  const auto regions = segment_planes(mesh, sp);
  out.regions = regions.size();
  if (regions.empty()) throw std::runtime_error("degenerate geometry: no plane with enough area");

  // The carving box, padded so that the outermost walls cut off slabs thicker than δ.
  const double pad = std::max(2 * out.cell_size, 4 * out.dist);
  BBox cbox = out.box;
  cbox.lo -= Vec3{pad, pad, pad};
  cbox.hi += Vec3{pad, pad, pad};
  out.complex = std::make_unique<CellComplex>(*out.planes, cbox);
  std::vector<CarvePlane> cps;
  std::vector<double> cp_area;  // per carving plane: the area of the face (or missing face) it is from
  // Registers a carving plane; a plane's label is the first one given to it.
  auto add_carve_plane = [&](const Plane& pl, const BBox& where, int32_t label, double area) {
    const uint32_t id = out.planes->add(pl, PlaneOrigin::Region);
    if (out.plane_label.size() <= id) out.plane_label.resize(id + 1, -1);
    if (out.plane_label[id] < 0) out.plane_label[id] = label;
    cps.push_back({id, where});
    cp_area.push_back(area);
    return id;
  };
  std::vector<uint32_t> region_plane;
  std::vector<uint32_t> missing_face_plane;  // hole and open-boundary planes, with their boxes
  std::vector<BBox> missing_face_box;
  for (const auto& r : regions) region_plane.push_back(add_carve_plane(r.plane, r.bbox, r.semantic, r.area));
  // Fitted planes that share an input corner meet there exactly (else the carving may refuse
  // one of them at a hair-close vertex); the tolerance is that hair.
  if (p.snap_corners)
    out.anchored_planes = snap_corners(mesh, regions, region_plane, *out.planes, 0.1 * out.dist);
  // Planes of the input's holes (missing faces), after the regions; a virtual face.
  const std::vector<HolePlane> holes = hole_planes(mesh, out.dist, sp.min_area, out.box.lo.z);
  for (const HolePlane& h : holes) {
    missing_face_plane.push_back(
        add_carve_plane(h.plane, h.bbox, mesh.label_index("ClosureSurface"), h.area));
    missing_face_box.push_back(h.bbox);
    ++out.hole_planes;
  }
  // The ground level of the vertical vote: the input's lowest height, or for a model with neither
  // a ground nor walls (roofs only) the terrain height the file gives, when it is lower (§6.4).
  double ground_z = out.box.lo.z;
  if (std::isfinite(terrain_z) && out.up_axis == 2 && !open.has_ground) {
    bool walls = false;
    for (const Polygon& f : mesh.faces) {
      const FaceGeometry g = face_geometry(mesh, f);
      walls |= g.area > 0 && std::abs(g.normal.z) < 0.17;
    }
    const double t = terrain_z - out.offset.z;
    if (!walls && t < out.box.lo.z - out.dist) {
      ground_z = t;
      out.ground_from_terrain = true;
      cbox.lo.z = std::min(cbox.lo.z, ground_z - pad);
    }
  }
  // An open input carves its missing faces (hole planes) in their turn among the regions, by size
  // (stable: the regions keep their order). After a smaller region that shares a corner with it
  // (a few-centimetre wall at the end of a missing party wall) a missing face's plane would meet
  // only cells that the smaller plane already cut through that corner, and the hair rule keeps it
  // out of them: a wedge of air or of the building stays mislabelled (docs/algorithm.md §6.4).
  // The open boundary's vertical planes stay after them: ordered by size too, they made walls-less
  // models worse (docs/known-weaknesses.md).
  if (out.open_input) {
    const size_t n = regions.size() + out.hole_planes;
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cp_area[a] > cp_area[b]; });
    std::vector<CarvePlane> sorted;
    for (size_t i : order) sorted.push_back(cps[i]);
    std::copy(sorted.begin(), sorted.end(), cps.begin());
  }
  out.open_boundary_length = open.uncovered_length;

  const bool vertical_ok = open.vertical_applicable();
  const bool want_vertical =
      p.oracle == "vertical" || (p.oracle != "parity" && out.open_input && vertical_ok);
  // (also when parity labels first but the vertical vote may label a second time, §6.5)
  if (want_vertical || (out.open_input && vertical_ok)) {
    for (const HolePlane& h : boundary_wall_planes(
             open, out.dist, out.angle_rad, sp.min_area / std::max(out.box.hi.z - out.box.lo.z, out.dist),
             ground_z, out.box.hi.z)) {
      // A plane the carving already has (the rest of a wall whose shared part was left out) is
      // offered where the open boundary is too: its box grows to cover it.
      bool known = false;
      for (CarvePlane& c : cps)
        if (same_plane_in_box((*out.planes)[c.plane], h.plane, out.angle_rad, out.dist, out.box)) {
          c.bbox.add(h.bbox.lo);
          c.bbox.add(h.bbox.hi);
          known = true;
          break;
        }
      if (known) continue;
      missing_face_plane.push_back(
          add_carve_plane(h.plane, h.bbox, mesh.label_index("ClosureSurface"), h.area));
      missing_face_box.push_back(h.bbox);
      ++out.boundary_wall_planes;
    }
  }
  // A missing face's plane that passes a hair from the line of two region planes would be refused
  // by the hair rule wherever that line bounds a cell: it is anchored on the line (§4, §7.4).
  if (p.snap_corners)
    out.anchored_planes += snap_to_lines(missing_face_plane, missing_face_box, region_plane, *out.planes,
                                         0.1 * out.dist, out.dist);
  // The input's lowest level, offered last: caps open bottoms (walls and roof without a floor),
  // which would otherwise leave the cell hanging down to the padded box.
  BBox ground_box = out.box;
  ground_box.lo.z = ground_z;
  add_carve_plane({{0, 0, 1}, -ground_z}, ground_box, mesh.label_index("GroundSurface"), 0.0);
  out.labels = mesh.semantic_labels;

  // Oracles and carving.
  const TriangleSoup tris = triangulate(mesh);
  if (tris.triangles.empty()) throw std::runtime_error("degenerate geometry: nothing to triangulate");
  const TriangleSoup& osoup = oracle_tris.triangles.empty() ? tris : oracle_tris;
  const PolygonMesh& omesh = oracle_tris.triangles.empty() ? mesh : oracle_mesh;
  InsideOracle oracle(osoup, p.oracle_rays, p.seed);
  // The fast path (docs/algorithm.md §6.6): a closed input checked to be a valid solid with exact
  // predicates is labelled by one clean ray per point.
  if (!p.fast_path) {
    out.fast_path_reason = "fast path off";
  } else if (out.open_input) {
    out.fast_path_reason = "open input";
  } else if (oracle_tris.triangles.empty()) {
    out.fast_path_reason = "no valid face at the oracle's weld";
  } else {
    checking.wait();
    // (non-planar faces, 203/204, do not matter to the rays)
    out.fast_path = check.closed_manifold;
    out.fast_path_reason = "not a closed 2-manifold";
    for (const SolidError& e : check.errors)
      if (e.code != solid_code::kNonPlanarPolygon && e.code != solid_code::kNonPlanarNormals) {
        out.fast_path_reason = std::to_string(e.code) + " " + e.name;
        break;
      }
    if (out.fast_path) out.fast_path_reason.clear();
  }
  oracle.set_valid_solid(out.fast_path);
  oracle.set_merge_distance(out.dist);
  oracle.set_enclosure(p.fill_enclosed);
  const std::vector<uint8_t> cover = cover_triangles(osoup, omesh);
  const VerticalOracle vertical_input(osoup, cover, out.dist, ground_z);
  // Floors of parts whose ground is missing above the lowest level count as ground faces of the
  // vertical vote (docs/algorithm.md §6.4).
  std::optional<VerticalOracle> vertical_floors;
  const bool horizontal_holes = std::any_of(holes.begin(), holes.end(), [&](const HolePlane& h) {
    return h.loop.size() >= 3 && std::abs(h.plane.n.z) >= std::cos(out.angle_rad);
  });
  std::optional<VerticalOracle> all_surfaces;  // every triangle, walls too: what lies below a hole
  if (horizontal_holes)
    all_surfaces.emplace(osoup, std::vector<uint8_t>(osoup.triangles.size(), 1), out.dist, ground_z);
  if (const TriangleSoup floors =
          horizontal_holes ? open_bottoms(holes, vertical_input, *all_surfaces, out.dist, out.angle_rad)
                           : TriangleSoup{};
      !floors.triangles.empty()) {
    TriangleSoup with = osoup;
    std::vector<uint8_t> with_cover = cover;
    with_cover.resize(with.triangles.size(), 0);
    const uint32_t base = static_cast<uint32_t>(with.vertices.size());
    with.vertices.insert(with.vertices.end(), floors.vertices.begin(), floors.vertices.end());
    for (const auto& t : floors.triangles) {
      with.triangles.push_back({base + t[0], base + t[1], base + t[2]});
      with.source_face.push_back(UINT32_MAX);
      with_cover.push_back(1);
    }
    vertical_floors.emplace(with, with_cover, out.dist, ground_z);
    out.open_bottom_triangles = floors.triangles.size();
  }
  const VerticalOracle& vertical = vertical_floors ? *vertical_floors : vertical_input;

  CarveParams cp;
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
  const SurfaceIndex index(tris);

  // One labelling: carving with one oracle, then the singleton repairs (§8).
  struct Labelling {
    std::unique_ptr<CellComplex> complex;
    CarveResult carve;
    std::vector<uint32_t> inside;
    std::vector<std::string> problems;
    double volume = 0;
  };
  auto label = [&](bool use_vertical) {
    Labelling l;
    l.complex = std::make_unique<CellComplex>(*out.planes, cbox);
    CarveParams c = cp;
    c.oracle_box = use_vertical ? vertical.bbox() : oracle.bbox();
    // A cell the surface does not touch is uniformly inside or outside, except across the
    // oracle's box: beyond it everything is outside, so a cell hanging out of an open bottom (no
    // floor face to touch) is not uniform and needs the full vote.
    const BBox ob = c.oracle_box;
    c.surface_touches = [&index, ob](const BBox& b) {
      return index.touches(b) || (ob.overlaps(b) && !ob.contains(b));
    };
    // A valid solid's cell that the surface reaches at most a hair into (fitting noise of the
    // faces along its facets) is uniform but for that band (docs/algorithm.md §7.3).
    if (out.fast_path && !use_vertical && p.grazed_cells) {
      const double hair = 0.1 * out.dist;
      c.surface_enters = [&index, hair](const std::vector<Plane>& outward, const BBox& b) {
        return index.enters(outward, b, hair);
      };
      c.band = out.dist;
    }
    l.carve = carve(
        *l.complex, cps,
        [&](const std::vector<Vec3>& pts, const std::vector<uint64_t>& ids, std::vector<uint8_t>& flags) {
          if (use_vertical) vertical.classify(pts, flags);
          else oracle.classify(pts, ids, flags);
        },
        c, deadline);
    l.inside = l.carve.inside;
    if (l.inside.empty()) return l;
    // Slabs and wedges thinner than two steps of the output grid cannot be written valid (§8).
    if (p.output_grid > 0) {
      double thin = 0;
      if (const size_t n = flip_thin_cells(*l.complex, l.inside, 2 * p.output_grid, thin))
        l.problems.push_back("changed the side of " + std::to_string(n) +
                             " cell(s) thinner than two steps of the output grid (volume " +
                             std::to_string(thin) + ")");
    }
    // A void enclosed by the building would be an inner shell of the cell and of a part: filled.
    double filled = 0;
    size_t cavities = fill_cavities(*l.complex, l.inside, filled);
    double flipped = 0;
    if (const size_t n = remove_pinch_edges(*l.complex, l.inside, flipped))
      l.problems.push_back("changed the side of " + std::to_string(n) + " cell(s) at pinch edges (volume " +
                           std::to_string(flipped) + ") to make the singleton cell 2-manifold");
    cavities += fill_cavities(*l.complex, l.inside, filled);
    if (cavities)
      l.problems.push_back("filled " + std::to_string(cavities) + " enclosed outside cell(s) (volume " +
                           std::to_string(filled) + ") so that the singleton cell has no cavity");
    std::sort(l.inside.begin(), l.inside.end());
    if (!l.inside.empty()) l.volume = surface_volume(*l.complex, l.inside);
    return l;
  };

  // The independent estimate (§6.5): the input's own volume when it is closed and consistently
  // oriented; for an open input the vertical vote integrated over columns. A closed input without
  // a consistent orientation has none: vertical columns merge crossings within δ and miscount
  // thin slabs (sample20: 881,404 m³ against the paper's 937,784 and parity's 938,034).
  VolumeCheck& vc = out.volume_check;
  if (const double v = closed_volume(osoup); v > 0 && !out.open_input) {
    vc.estimate = v;
    vc.method = "signed volume";
  } else if (vertical.valid() && vertical_ok && (out.open_input || want_vertical)) {
    vc.estimate = vertical.volume();
    vc.method = "vertical columns";
  }
  const bool first_vertical = want_vertical && vertical.valid();
  Labelling chosen = label(first_vertical);
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
      first_vertical || (vertical.valid() && vertical_ok &&
                         (out.open_input || vc.method == "signed volume" || chosen.inside.empty()));
  if ((chosen.inside.empty() || disagrees) && other_possible && Clock::now() < deadline) {
    vc.relabelled = true;
    Labelling second = label(!first_vertical);
    const bool better =
        !second.inside.empty() && (chosen.inside.empty() || off(second.volume) < off(chosen.volume));
    if (better) {
      chosen = std::move(second);
      vc.oracle = first_vertical ? "parity" : "vertical";
    }
  }
  out.complex = std::move(chosen.complex);
  const CarveResult& cr = chosen.carve;
  out.cells = cr.cells;
  out.inside_cells = cr.inside.size();
  out.oracle_points = cr.points;
  out.truncated = cr.truncated;
  if (cr.inside.empty()) throw std::runtime_error("no interior: the oracle found no inside cell");
  out.problems.insert(out.problems.end(), chosen.problems.begin(), chosen.problems.end());
  std::vector<uint32_t> inside = std::move(chosen.inside);
  if (inside.empty()) throw std::runtime_error("no interior left after removing pinch edges");
  vc.cell = chosen.volume;
  vc.ratio = vc.estimate > 0 ? vc.cell / vc.estimate : 1.0;
  vc.flagged = p.volume_check > 0 && vc.estimate > 0 && off(vc.cell) > p.volume_check;
  if (vc.flagged)
    out.problems.push_back("volume check: cell " + std::to_string(vc.cell) + " vs " + vc.method +
                           " estimate " + std::to_string(vc.estimate) + " (ratio " +
                           std::to_string(vc.ratio) + ", oracle " + vc.oracle +
                           (vc.relabelled ? ", after a second labelling" : "") + ")");
  auto comps = connected_components(*out.complex, inside);
  double total = 0;
  std::vector<SingletonComponent> sc;
  for (auto& c : comps) {
    const double v = surface_volume(*out.complex, c);
    total += v;
    sc.push_back({std::move(c), v});
  }
  std::stable_sort(sc.begin(), sc.end(), [](const auto& a, const auto& b) { return a.volume > b.volume; });
  for (auto& c : sc) {
    if (c.volume < p.min_component_fraction * total) {
      ++out.dropped_components;
      out.dropped_volume += c.volume;
    } else {
      out.components.push_back(std::move(c));
    }
  }
  if (out.dropped_components)
    out.problems.push_back("dropped " + std::to_string(out.dropped_components) +
                           " small interior component(s), volume " + std::to_string(out.dropped_volume));

  // Closedness and fidelity of the whole singleton (all components).
  std::vector<uint32_t> all;
  for (const auto& c : out.components) all.insert(all.end(), c.cells.begin(), c.cells.end());
  const Surface s = extract_surface(*out.complex, all);
  out.closed = s.closed();
  out.manifold = s.nonmanifold_edges == 0;
  if (p.compute_hausdorff) {
    auto f = std::make_shared<FidelityInputs>();
    boundary_triangles(*out.complex, all, Vec3{}, f->cell.vertices, f->cell.triangles);
    f->step = std::max(out.box.diagonal() * p.hausdorff_error * 10, out.cell_size / 2);
    f->input = tris;
    out.pending_fidelity = std::move(f);
    if (!defer_fidelity) measure_fidelity(out);
  }
  out.seconds = seconds_since(t0);
  return out;
}

}  // namespace mc
