// The metric frame a building is decomposed in, and its map to and from the file's coordinates
// (docs/algorithm.md §2.1). Every threshold of the algorithm and every check of an output part is
// in metres; a file's coordinates may be metres, another linear unit (US survey feet), or degrees
// of latitude and longitude with heights in metres (geographic CRSs such as EPSG:4979 or 6697),
// or earth-centred, earth-fixed metres (geocentric CRSs such as EPSG:4978, where z is not up).
//
// Geographic (and geocentric) coordinates are mapped to a transverse Mercator projection whose central
// meridian and origin are the building's own centre (GeographicLib's TransverseMercator on the WGS84
// ellipsoid, scale 1 on the central meridian), heights kept: the frame is conformal, its scale
// error is k - 1 = x² / 2R² (1.2e-8 at 1 km from the centre, far below any tolerance), and a roof
// of constant ellipsoidal height stays flat (a local tangent plane would bend it by d² / 2R:
// 0.2 mm at 50 m, 2 cm at 500 m).
#pragma once
#include <string>
#include <vector>

#include "core/polygon_mesh.hpp"
#include "core/vec3.hpp"

namespace mc {

// What a file's coordinates are (filled by the readers from the file's CRS: io/crs.hpp).
struct CoordinateSystem {
  enum class Kind { Metric, Scaled, Geographic, Geocentric };
  Kind kind = Kind::Metric;
  // Geographic: the first coordinate is the latitude (CityGML follows the CRS's axis order, which
  // is latitude first for EPSG:4326/4979/6697; CityJSON files write longitude first).
  bool lat_first = false;
  // Metres per unit: horizontal (Scaled only) and vertical (Scaled and Geographic).
  double horizontal_unit = 1, vertical_unit = 1;

  bool metric() const { return kind == Kind::Metric && vertical_unit == 1; }
  bool geographic() const { return kind == Kind::Geographic; }
  // Degrees or earth-centred metres: the working frame is a per-building projection.
  bool projected_per_building() const { return kind == Kind::Geographic || kind == Kind::Geocentric; }
  // "metres", "0.3048006096 m per unit", "degrees (longitude, latitude), heights in metres", ...
  std::string describe() const;
};

class WorkingFrame {
 public:
  // The identity (metric coordinates).
  WorkingFrame() = default;
  // The frame of a building whose file coordinates are `points` (the centre of their box is the
  // origin of a geographic frame). A geographic building whose latitudes are out of range in the
  // declared axis order but not in the other (a CityJSON file written latitude first) is read in
  // the other order, and `swapped()` says so.
  WorkingFrame(const CoordinateSystem& cs, const std::vector<Vec3>& points);

  bool identity() const { return kind_ == CoordinateSystem::Kind::Metric && vscale_ == 1; }
  bool swapped() const { return swapped_; }
  Vec3 to_metric(const Vec3& file) const;
  Vec3 to_file(const Vec3& metric) const;
  void to_metric(std::vector<Vec3>& points) const;
  void to_metric(PolygonMesh& mesh) const { to_metric(mesh.vertices); }
  void to_file(std::vector<Vec3>& points) const;
  // The geographic frame's origin (degrees) and central meridian; 0 otherwise.
  double origin_lat() const { return lat0_; }
  double origin_lon() const { return lon0_; }

 private:
  CoordinateSystem::Kind kind_ = CoordinateSystem::Kind::Metric;
  bool lat_first_ = false, swapped_ = false;
  double hscale_ = 1, vscale_ = 1;
  double lat0_ = 0, lon0_ = 0, y0_ = 0;  // geographic: origin, and its northing from the equator
};

}  // namespace mc
