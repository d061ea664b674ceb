#include "core/carving_planes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/corner_snap.hpp"
#include "core/segmentation.hpp"
#include "core/soup.hpp"

namespace mc {

namespace {

// The carving planes being registered: a plane's label is the first one given to it; `area` per
// carving plane is the area of the face (or missing face) it is from.
struct PlaneList {
  CarvingPlanes& cp;
  Preprocessed& out;
  std::vector<double> area;
  std::vector<uint32_t> missing_face_plane;  // hole and open-boundary planes, with their boxes
  std::vector<BBox> missing_face_box;
  uint32_t add(const Plane& pl, const BBox& where, int32_t label, double face_area) {
    const uint32_t id = out.planes->add(pl, PlaneOrigin::Region);
    if (out.plane_label.size() <= id) out.plane_label.resize(id + 1, -1);
    if (out.plane_label[id] < 0) out.plane_label[id] = label;
    cp.planes.push_back({id, where});
    area.push_back(face_area);
    return id;
  }
  void add_missing(const HolePlane& h, int32_t label) {
    missing_face_plane.push_back(add(h.plane, h.bbox, label, h.area));
    missing_face_box.push_back(h.bbox);
  }
};

// The ground level of the vertical vote: the input's lowest height, or for a model with neither
// a ground nor walls (roofs only) the terrain height the file gives, when it is lower (§6.4).
void ground_level(const PolygonMesh& mesh, const OpenInput& open, double terrain_z, double pad,
                  Preprocessed& out, CarvingPlanes& cp) {
  cp.ground_z = out.box.lo.z;
  if (!std::isfinite(terrain_z) || out.up_axis != 2 || open.has_ground) return;
  bool walls = false;
  for (const Polygon& f : mesh.faces) {
    const FaceGeometry g = face_geometry(mesh, f);
    walls |= g.area > 0 && std::abs(g.normal.z) < 0.17;
  }
  const double t = terrain_z - out.offset.z;
  if (!walls && t < out.box.lo.z - out.dist) {
    cp.ground_z = t;
    out.ground_from_terrain = true;
    cp.box.lo.z = std::min(cp.box.lo.z, cp.ground_z - pad);
  }
}

// An open input carves its missing faces (hole planes) in their turn among the regions, by size
// (stable: the regions keep their order). After a smaller region that shares a corner with it (a
// few-centimetre wall at the end of a missing party wall) a missing face's plane would meet only
// cells that the smaller plane already cut through that corner, and the hair rule keeps it out
// of them: a wedge of air or of the building stays mislabelled (docs/algorithm.md §6.4). The
// open boundary's vertical planes stay after them: ordered by size too, they made walls-less
// models worse (docs/known-weaknesses.md).
void order_by_area(size_t n, PlaneList& list) {
  std::vector<CarvePlane>& cps = list.cp.planes;
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return list.area[a] > list.area[b]; });
  std::vector<CarvePlane> sorted;
  for (size_t i : order) sorted.push_back(cps[i]);
  std::copy(sorted.begin(), sorted.end(), cps.begin());
}

// The open boundary's vertical planes (walls where the input has none). A plane the carving
// already has (the rest of a wall whose shared part was left out) is offered where the open
// boundary is too: its box grows to cover it.
void open_boundary_planes(PolygonMesh& mesh, const OpenInput& open, double min_area, PlaneList& list) {
  Preprocessed& out = list.out;
  CarvingPlanes& cp = list.cp;
  for (const HolePlane& h : boundary_wall_planes(open, out.dist, out.angle_rad,
                                                 min_area / std::max(out.box.hi.z - out.box.lo.z, out.dist),
                                                 cp.ground_z, out.box.hi.z)) {
    bool known = false;
    for (CarvePlane& c : cp.planes)
      if (same_plane_in_box((*out.planes)[c.plane], h.plane, out.angle_rad, out.dist, out.box)) {
        c.bbox.add(h.bbox.lo);
        c.bbox.add(h.bbox.hi);
        known = true;
        break;
      }
    if (known) continue;
    list.add_missing(h, mesh.label_index("ClosureSurface"));
    ++out.boundary_wall_planes;
  }
}

}  // namespace

CarvingPlanes carving_planes(InputFrame& in, const OpenInput& open, const PreprocessParams& p,
                             double terrain_z, Preprocessed& out) {
  CarvingPlanes cp;
  PolygonMesh& mesh = in.mesh;
  PreprocessParams resolved = p;
  resolved.cell_size = out.cell_size;
  resolved.dist_thresh = out.dist;
  const SegmentationParams sp = segmentation_params(resolved);
  const auto regions = segment_planes(mesh, sp);
  out.regions = regions.size();
  if (regions.empty()) throw std::runtime_error("degenerate geometry: no plane with enough area");
  // The carving box, padded so that the outermost walls cut off slabs thicker than δ.
  const double pad = std::max(2 * out.cell_size, 4 * out.dist);
  cp.box = out.box;
  cp.box.lo -= Vec3{pad, pad, pad};
  cp.box.hi += Vec3{pad, pad, pad};
  // (the complex registers the box's planes first: their ids come before the regions')
  out.complex = std::make_unique<CellComplex>(*out.planes, cp.box);
  PlaneList list{cp, out, {}, {}, {}};
  std::vector<uint32_t> region_plane;
  for (const auto& r : regions) region_plane.push_back(list.add(r.plane, r.bbox, r.semantic, r.area));
  // Fitted planes that share an input corner meet there exactly (else the carving may refuse
  // one of them at a hair-close vertex); the tolerance is that hair.
  if (p.snap_corners)
    out.anchored_planes = snap_corners(mesh, regions, region_plane, *out.planes, 0.1 * out.dist);
  // Planes of the input's holes (missing faces), after the regions; a virtual face.
  cp.holes = hole_planes(mesh, out.dist, sp.min_area, out.box.lo.z);
  for (const HolePlane& h : cp.holes) {
    list.add_missing(h, mesh.label_index("ClosureSurface"));
    ++out.hole_planes;
  }
  ground_level(mesh, open, terrain_z, pad, out, cp);
  if (out.open_input) order_by_area(regions.size() + out.hole_planes, list);
  out.open_boundary_length = open.uncovered_length;
  cp.vertical_applicable = open.vertical_applicable();
  cp.want_vertical =
      p.oracle == "vertical" || (p.oracle != "parity" && out.open_input && cp.vertical_applicable);
  // (also when parity labels first but the vertical vote may label a second time, §6.5)
  if (cp.want_vertical || (out.open_input && cp.vertical_applicable))
    open_boundary_planes(mesh, open, sp.min_area, list);
  // A missing face's plane that passes a hair from the line of two region planes would be refused
  // by the hair rule wherever that line bounds a cell: it is anchored on the line (§4, §7.4).
  if (p.snap_corners)
    out.anchored_planes += snap_to_lines(list.missing_face_plane, list.missing_face_box, region_plane,
                                         *out.planes, 0.1 * out.dist, out.dist);
  // The input's lowest level, offered last: caps open bottoms (walls and roof without a floor),
  // which would otherwise leave the cell hanging down to the padded box.
  BBox ground_box = out.box;
  ground_box.lo.z = cp.ground_z;
  list.add({{0, 0, 1}, -cp.ground_z}, ground_box, mesh.label_index("GroundSurface"), 0.0);
  out.labels = mesh.semantic_labels;
  return cp;
}

}  // namespace mc
