// Plane segmentation of a building surface (docs/algorithm.md §3): region growing over faces,
// near-duplicate plane merge, area filter. Our own grower (not CGAL 5.5's) so that the normal
// test is unoriented (flipped faces join their wall) and the result is deterministic.
#pragma once
#include <cstdint>
#include <vector>

#include "core/params.hpp"
#include "core/plane.hpp"
#include "core/polygon_mesh.hpp"

namespace mc {

struct SegmentationParams {
  double max_distance = 0.25;    // region growing: max vertex distance to the region plane
  double max_angle_deg = 10;     // region growing: max unoriented face-normal angle
  double angle_thresh_deg = 10;  // θa of the near-duplicate merge
  double dist_thresh = 0.25;     // δ of the near-duplicate merge
  double min_area = 0;           // groups with a smaller total area are dropped (cell_size²)
  int min_region = 1;            // minimum faces per grown region
};

// Fills SegmentationParams from resolved preprocessing parameters (cell_size and dist_thresh
// must already be > 0; max_distance <= 0 means dist_thresh).
SegmentationParams segmentation_params(const PreprocessParams& p);

struct PlaneRegion {
  // Unit normal; oriented to agree with the area-weighted majority of its faces' normals
  // (informative only: inputs may be inward-facing, never derive "outside" from it).
  Plane plane;
  std::vector<uint32_t> faces;  // face indices into the mesh, ascending
  double area = 0;              // sum of face areas
  BBox bbox;                    // of the faces' vertices
  int32_t semantic = -1;        // majority semantic label by area, -1 when none
};

// Regions sorted by decreasing area (ties: smallest first face). Faces are edge-adjacent when
// they share two vertex positions (exactly equal coordinates), so unmerged duplicate vertices
// do not split regions; run clean_soup first for tolerance-based merging. Degenerate faces
// (no normal) and faces of dropped groups belong to no region.
std::vector<PlaneRegion> segment_planes(const PolygonMesh& mesh, const SegmentationParams& p);

}  // namespace mc
