// Features from one CRS to another with PROJ (`morphcut-city --output-crs`, `morphcut-city
// reproject`; docs/output-format.md, "Coordinates"). Horizontal coordinates are transformed;
// heights are kept as they are: PROJ runs offline, without the geoid grids a change of vertical
// datum needs, and a grid-free guess would move every height by a different few centimetres.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "io/feature_source.hpp"

namespace mc::io {

class Reprojector {
 public:
  // Throws std::runtime_error when either CRS is unknown or PROJ has no transformation.
  Reprojector(const std::string& from, const std::string& to);
  ~Reprojector();
  Reprojector(const Reprojector&) = delete;
  Reprojector& operator=(const Reprojector&) = delete;
  // (x, y) transformed, z kept; geographic coordinates are longitude first on both sides. Not
  // thread-safe (one PROJ object).
  Vec3 apply(const Vec3& p) const;
  // In place; throws std::runtime_error naming the first point PROJ cannot transform.
  void apply(std::vector<Vec3>& points) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The OGC URL CityJSON writes in metadata.referenceSystem for "EPSG:<code>" (any spelling
// normalize_crs() reads); the CRS as given otherwise.
std::string reference_system_url(const std::string& crs);

// Another source's features in CRS `to`: the header's referenceSystem, transform and
// geographicalExtent follow (the transform's scale is `scale` horizontally, or by default 1e-8
// for degrees and 0.001 for linear units, and the input's vertical scale), and every feature's
// vertices are transformed as it is read.
class ReprojectedSource : public SourceFilter {
 public:
  // `from` overrides the input's CRS (for a file that lost it); empty = the input's own.
  ReprojectedSource(std::unique_ptr<FeatureSource> in, const std::string& to,
                    std::optional<double> scale = std::nullopt, const std::string& from = "");
  bool next(Feature& out) override;

 private:
  std::unique_ptr<Reprojector> proj_;
};

}  // namespace mc::io
