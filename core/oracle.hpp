// Inside/outside oracle over a triangle soup (docs/algorithm.md §6): Embree ray casting, parity
// of the number of distinct surface crossings along several upward rays, majority vote.
// Rays go into the upper hemisphere (elevation 30°–90° about +z) so an open-bottom building
// (walls and roof, no floor) still encloses its interior. The soup must be z-up.
#pragma once
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "core/plane.hpp"
#include "core/soup.hpp"
#include "core/vec3.hpp"

namespace mc {

class InsideOracle {
 public:
  // `rays` per point (odd avoids ties; a tie counts as outside). Directions are jittered per
  // point from (seed, point_id) alone, so results do not depend on threads or call order.
  InsideOracle(const TriangleSoup& soup, int rays, uint64_t seed);
  ~InsideOracle();
  InsideOracle(const InsideOracle&) = delete;
  InsideOracle& operator=(const InsideOracle&) = delete;

  // Thread-safe. Points outside the soup's bounding box are outside.
  bool inside(const Vec3& p, uint64_t point_id) const;
  // out[i] = inside(pts[i], first_id + i), computed in parallel (TBB).
  void classify(const std::vector<Vec3>& pts, uint64_t first_id, std::vector<uint8_t>& out) const;
  // out[i] = inside(pts[i], ids[i]), computed in parallel (TBB).
  void classify(const std::vector<Vec3>& pts, const std::vector<uint64_t>& ids,
                std::vector<uint8_t>& out) const;

  // Number of distinct surface crossings along the ray p + t·dir, t > 0 (hits at nearly equal
  // t merged, so a ray through a shared edge counts once). Exposed for tests and diagnostics.
  // With several closed shells the count is reduced to its parity over the union (1 = inside some
  // shell, 2 = none).
  int count_crossings(const Vec3& p, const Vec3& dir) const;
  // The same; `clean` tells whether no two crossings came within twice the merge distance of
  // each other (no edge, vertex or second surface near the ray) and the soup is one parity group.
  int count_crossings(const Vec3& p, const Vec3& dir, bool* clean) const;
  const BBox& bbox() const { return box_; }
  // Hits closer than `t` along a ray count as one crossing. Preprocessing sets it to δ: surfaces
  // within the model tolerance are one surface (duplicate or doubled walls), as in plane merging.
  void set_merge_distance(double t);
  // Enclosure fallback: a point the parity vote calls outside, but from which no ray of a fixed
  // fan (16 azimuths x elevations 0°..90°) escapes, is enclosed by the surface and counts as
  // inside. Parity breaks on interior sheets (storey floors modelled as faces inside a solid,
  // glued to the walls along non-manifold edges); enclosure does not. Downward rays are left out
  // so that open-bottom buildings are not penalised. Off by default. Only a soup with interior
  // sheets needs it, and those are glued to the walls along edges with more than two triangles:
  // without such edges it stays off (parity is right there, and the extra inside points would
  // only perturb the carving).
  void set_enclosure(bool on) { enclosure_ = on && nonmanifold_edges_ > 0; }
  // The soup is a valid solid (closed, 2-manifold, outward, not self-intersecting, checked with
  // exact predicates): a ray's parity is the point's containment unless the ray passes within
  // the merge distance of an edge or of a second surface, which a clean ray does not, so a clean
  // first ray decides a point and the vote runs only for the others. A soup with thin wedges
  // (`thin_wedges()`), where the vote's merged crossings and one exact ray disagree most, needs
  // two clean rays that agree (docs/algorithm.md §6.6).
  void set_valid_solid(bool on) { valid_solid_ = on; }
  // Two triangles along an edge meet at less than kThinWedgeDegrees on one side.
  bool thin_wedges() const { return thin_wedges_; }
  static constexpr double kThinWedgeDegrees = 45;
  size_t nonmanifold_edges() const { return nonmanifold_edges_; }
  // The direction of the point's ray k (exposed for tests and diagnostics).
  Vec3 ray(uint64_t point_id, int k) const { return ray_direction(splitmix_base(point_id), k); }
  // True when no ray of the fan from p escapes (exposed for tests and diagnostics).
  bool enclosed(const Vec3& p, uint64_t point_id) const;

 private:
  void assign_groups(const TriangleSoup& soup);
  Vec3 ray_direction(uint64_t base, int k) const;  // ray k of the point with seed `base`
  // count_crossings from a ray's hits (t along dir, primitive); sorts them.
  int crossings(std::vector<std::pair<float, unsigned>>& hits, const Vec3& dir, bool* clean) const;
  uint64_t splitmix_base(uint64_t point_id) const;  // that seed for a point
  struct Impl;
  std::unique_ptr<Impl> impl_;
  BBox box_;
  int rays_;
  uint64_t seed_;
  bool enclosure_ = false;
  bool valid_solid_ = false;
  bool thin_wedges_ = false;
  size_t nonmanifold_edges_ = 0;
};

}  // namespace mc

namespace mc {

// The vertical "roof-over-ground" vote for open inputs (docs/algorithm.md §6.4): parity of the
// crossings of the vertical ray p + t·e_z (t > 0) with the input's *cover* triangles (roofs,
// grounds and other non-vertical surfaces; walls and interior surfaces are left out), above the
// ground level. Walls are parallel to the ray, so missing walls (party walls, gaps, a wall-less
// model) change nothing; a missing ground is replaced by the ground level (a column with an odd
// number of crossings starts there). Deterministic (no random directions).
class VerticalOracle {
 public:
  // cover[i] != 0: soup triangle i takes part. ground_z: the ground level (the input's lowest
  // height); points below it are outside. Hits closer than merge_dist along a ray are one.
  VerticalOracle(const TriangleSoup& soup, const std::vector<uint8_t>& cover, double merge_dist,
                 double ground_z);
  ~VerticalOracle();
  VerticalOracle(const VerticalOracle&) = delete;
  VerticalOracle& operator=(const VerticalOracle&) = delete;

  bool valid() const { return box_.valid(); }  // some cover triangle
  // Box of the cover triangles, from the ground level up; everything outside it is outside.
  const BBox& bbox() const { return box_; }
  bool inside(const Vec3& p) const;                                              // thread-safe
  void classify(const std::vector<Vec3>& pts, std::vector<uint8_t>& out) const;  // parallel (TBB)
  // The volume the vote labels inside, integrated over a grid of vertical columns of about
  // `columns` columns over the cover's horizontal box (an estimate independent of the carving).
  double volume(int columns = 4096) const;
  // Heights where the vertical line through (x, y) crosses the cover, ascending, merged.
  std::vector<double> crossings(double x, double y) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  BBox box_;
  double ground_z_ = 0;
};

}  // namespace mc
