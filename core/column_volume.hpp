// The exact inside volume of a convex cell for a valid solid (docs/design.md "Inside volume by
// columns", docs/algorithm.md §7.3). For a closed, outward-oriented surface the inside indicator
// of a point is the signed number of triangles above it (+1 for a triangle facing up, −1 for
// one facing down), so the inside volume of a cell C is
//     Σ_t sign(n_z(t)) · vol(C ∩ {below t's plane} ∩ {over t's projection}),
// each term a convex polytope clipped from C by at most four planes. The answer depends on the
// geometry only: no sample points, no seed, the same in any frame up to rounding.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/plane.hpp"
#include "core/soup.hpp"

namespace mc {

// A convex polytope as its faces' vertex loops, each counter-clockwise seen from outside, stored
// one after another (face f is points[f == 0 ? 0 : ends[f - 1], ends[f])): clipping reuses the
// buffers instead of allocating a vector per face.
struct ConvexPolytope {
  std::vector<Vec3> points;
  std::vector<uint32_t> ends;
  size_t face_count() const { return ends.size(); }
  bool empty() const { return ends.empty(); }
  uint32_t face_begin(size_t f) const { return f == 0 ? 0 : ends[f - 1]; }
  // Ends the face whose points were pushed since the last one (fewer than 3: dropped).
  void close_face() {
    const uint32_t begin = ends.empty() ? 0 : ends.back();
    if (points.size() - begin >= 3) ends.push_back(static_cast<uint32_t>(points.size()));
    else points.resize(begin);
  }
  void clear() {
    points.clear();
    ends.clear();
  }
};

// Volume by the divergence theorem (fans from the first vertex; 0 for an empty polytope).
double polytope_volume(const ConvexPolytope& p);

// The part of `p` where n·x + d <= 0 (vertices within `eps` of the plane count as on it), into
// `out`; the cut is closed by a new face on the plane. `out` must not be `p`.
void clip_polytope(const ConvexPolytope& p, const Plane& keep_below, double eps, ConvexPolytope& out);

class ColumnVolume {
 public:
  // `soup` must be closed and consistently oriented (a valid solid); its orientation (outward or
  // inward) is read from its signed volume. Triangles facing sideways (no projection) are left
  // out: they bound no column.
  explicit ColumnVolume(const TriangleSoup& soup);
  // How many triangles stand over or cross a cell with box `box` (the terms of its sum).
  size_t columns_over(const BBox& box) const { return candidates(box).size(); }
  // The volume of the convex cell `cell` (with box `box`) inside the surface; in [0, volume].
  // With `max_columns` > 0 and more terms than that: −1 (not computed).
  double inside(const ConvexPolytope& cell, const BBox& box, size_t max_columns = 0) const;

 private:
  struct Column {
    Vec3 a, b, c;  // counter-clockwise in plan
    double sign;   // +1 when the triangle faces up (outward), −1 down
    BBox box;
  };
  double under(const ConvexPolytope& cell, const Column& t, double eps) const;
  // The columns over the box; once more than `limit` are found, the search stops (the caller
  // only needs to know there are too many).
  std::vector<uint32_t> candidates(const BBox& box, size_t limit = SIZE_MAX) const;

  std::vector<Column> columns_;
  // A plan grid over the columns' boxes: cell (i, j) lists the columns whose box overlaps it.
  double x0_ = 0, y0_ = 0, step_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<uint32_t>> grid_;
  double scale_ = 1;  // the surface's box diagonal (tolerances)
};

}  // namespace mc
