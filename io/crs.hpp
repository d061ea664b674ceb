// Source CRS -> WGS84 longitude/latitude (degrees), for the centroids in the planners' CSV.
// Uses PROJ with the network disabled: no grid is ever downloaded. Without the optional grid
// files (Debian's proj-data lacks e.g. the Dutch RDNAPTRANS grids) PROJ falls back to the
// best grid-free operation (for RD New a 7-parameter Helmert, about 1 m accurate); that is
// ample for a centroid in a planner's table, and the transform is deterministic.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/working_frame.hpp"

namespace mc::io {

// "EPSG:28992" for the OGC spellings CityJSON uses ("https://www.opengis.net/def/crs/EPSG/0/
// 28992", "http://…", "urn:ogc:def:crs:EPSG::28992", "urn:ogc:def:crs:EPSG:9.8:28992", any
// case of "epsg:"); anything else is returned unchanged (PROJ strings, WKT, …).
std::string normalize_crs(const std::string& crs);

// What a CRS's coordinates are (core/working_frame.hpp), from PROJ's definition of it: geographic
// (degrees; any geographic 2D or 3D CRS, or a compound one with a geographic horizontal part),
// geocentric, projected in metres, or in another linear unit (the unit's metres per unit). An
// empty CRS is metric; one PROJ does not know is metric too, and `note` says why it is assumed.
// `axis_order_of_crs`: geographic coordinates are in the CRS's own axis order (GML); otherwise
// longitude first (CityJSON, GeoJSON).
CoordinateSystem coordinate_system(const std::string& crs, bool axis_order_of_crs, std::string* note);

class CrsTransformer {
 public:
  // Empty `crs` = none (valid() is false). A compound CRS (e.g. EPSG:7415 = RD New + NAP
  // height) is reduced to its horizontal part: heights do not change longitude/latitude.
  explicit CrsTransformer(const std::string& crs);
  ~CrsTransformer();
  CrsTransformer(CrsTransformer&&) noexcept;
  CrsTransformer& operator=(CrsTransformer&&) noexcept;

  bool valid() const;
  // Why valid() is false (empty when valid).
  const std::string& error() const;
  // {longitude, latitude} in degrees, or nullopt if invalid or the point cannot be transformed.
  // `z` is accepted for symmetry with the input but ignored: lon/lat depend on x/y only.
  // Thread-safe: PROJ objects are not, so each call locks this instance's mutex (a call costs
  // about a microsecond; the pipeline makes one per building).
  std::optional<std::pair<double, double>> to_lonlat(double x, double y, double z) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc::io
