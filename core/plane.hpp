// Planes and the plane registry: the single source of truth for plane ids (docs/algorithm.md §3.4).
// Planes are stored with a unit normal in a canonical orientation (first non-zero normal
// component positive), so a plane and its opposite share one id; which side is "outward" is
// always derived from the B-rep, never from the stored orientation.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace mc {

struct Plane {
  Vec3 n;        // unit normal
  double d = 0;  // n·x + d = 0
  double signed_distance(const Vec3& p) const { return dot(n, p) + d; }
  Vec3 project(const Vec3& p) const { return p - n * signed_distance(p); }
};

// Unit normal with canonical sign; returns false for a degenerate normal.
bool canonicalize(Plane& p);

struct BBox {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(const Vec3& p);
  bool valid() const { return lo.x <= hi.x; }
  Vec3 center() const { return (lo + hi) * 0.5; }
  double diagonal() const { return valid() ? norm(hi - lo) : 0.0; }
  std::array<Vec3, 8> corners() const;
  // Closed boxes: they share a point once each is grown by `grow`.
  bool overlaps(const BBox& o, double grow = 0) const {
    return lo.x <= o.hi.x + grow && o.lo.x <= hi.x + grow && lo.y <= o.hi.y + grow && o.lo.y <= hi.y + grow &&
           lo.z <= o.hi.z + grow && o.lo.z <= hi.z + grow;
  }
  // `o` lies inside this box grown by `grow`.
  bool contains(const BBox& o, double grow = 0) const {
    return o.lo.x >= lo.x - grow && o.lo.y >= lo.y - grow && o.lo.z >= lo.z - grow && o.hi.x <= hi.x + grow &&
           o.hi.y <= hi.y + grow && o.hi.z <= hi.z + grow;
  }
};

// "Same plane", box variant (docs/algorithm.md §3.4): normals within `angle_rad` (unoriented) and
// the 8 box corners projected on `a` lie within `dist` of `b`.
bool same_plane_in_box(const Plane& a, const Plane& b, double angle_rad, double dist, const BBox& box);

enum class PlaneClass : uint8_t { Vertical, Horizontal, Inclined };
// Pitch classes of docs/algorithm.md §3.5 with θa = angle_rad; `up` is the vertical axis.
PlaneClass classify_plane(const Plane& p, double angle_rad, const Vec3& up = {0, 0, 1});

enum class PlaneOrigin : uint8_t { Region, Box, Candidate };

class PlaneRegistry {
 public:
  // Returns the id of an identical (after canonicalisation, bit-equal) plane or adds it.
  // Throws std::invalid_argument for a degenerate normal.
  uint32_t add(Plane p, PlaneOrigin origin = PlaneOrigin::Region);
  // Returns the id of the first registered plane in `pool` that is the same plane as `p` (box
  // variant); otherwise adds `p`. Deterministic: the pool order decides ties.
  uint32_t add_snapped(Plane p, const std::vector<uint32_t>& pool, double angle_rad, double dist,
                       const BBox& box, PlaneOrigin origin = PlaneOrigin::Candidate);
  const Plane& operator[](uint32_t id) const { return planes_[id]; }
  PlaneOrigin origin(uint32_t id) const { return origins_[id]; }
  size_t size() const { return planes_.size(); }
  const std::vector<Plane>& planes() const { return planes_; }

  // Anchors plane `id` to the common point of three other planes: exact consumers (the cell
  // complex) build it through that exact point with its normal, so that four fitted planes
  // meeting at one corner really meet there (core/corner_snap.hpp). `d` is the double offset
  // through the double point, for measurements. Must happen before a complex uses the plane.
  void set_anchor(uint32_t id, const std::array<uint32_t, 3>& via, double d);
  // The anchor of `id`, or nullptr when it is a plain (n, d) plane.
  const std::array<uint32_t, 3>* anchor(uint32_t id) const {
    return id < anchors_.size() && anchors_[id][0] != UINT32_MAX ? &anchors_[id] : nullptr;
  }
  size_t num_anchored() const;

  // Anchors plane `id` to the line where planes `a` and `b` meet: exact consumers build it through
  // that exact line, turned about it to be as near `id`'s normal as the line allows (a plane that
  // passes a hair from such a line then contains it; docs/algorithm.md §4). `line` is the new
  // double plane, for measurements. Must happen before a complex uses the plane.
  void set_line_anchor(uint32_t id, uint32_t a, uint32_t b, const Plane& line);
  // The two planes of `id`'s line anchor, or nullptr.
  const std::array<uint32_t, 2>* line_anchor(uint32_t id) const {
    return id < line_anchors_.size() && line_anchors_[id][0] != UINT32_MAX ? &line_anchors_[id] : nullptr;
  }

 private:
  std::vector<Plane> planes_;
  std::vector<PlaneOrigin> origins_;
  std::vector<std::array<uint32_t, 3>> anchors_;       // UINT32_MAX = none
  std::vector<std::array<uint32_t, 2>> line_anchors_;  // UINT32_MAX = none
};

}  // namespace mc
