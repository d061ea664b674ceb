// The planners' GeoPackage (OUT.morphcut.gpkg, docs/massing.md): a `buildings` layer (each
// building's footprint polygon with every column of the planners' CSV) and a `parts` layer
// (each part's footprint polygon with its level, role, heights, volume and convexity), in the
// source CRS (its horizontal component), written with GDAL/OGR. Atomic like every output: the
// file is built as `<path>.tmp.<pid>.gpkg` and renamed over `path` by commit(); a writer that dies
// uncommitted removes it. Deterministic: fixed gpkg_contents timestamps (OGR_CURRENT_DATE), one
// transaction, features in call order.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ogr_geometry.h>

namespace mc::io {

// 2D polygons in model coordinates: rings[0] the outer ring, then holes (closing point not repeated).
using Ring2 = std::vector<std::array<double, 2>>;
using Polygon2 = std::vector<Ring2>;
using MultiPolygon2 = std::vector<Polygon2>;

// One polygon as OGR geometry (rings closed, rings of fewer than 3 points left out).
OGRPolygon to_ogr(const Polygon2& poly);

enum class GpkgType { Text, Integer, Real };

struct GpkgColumn {
  std::string name;
  GpkgType type = GpkgType::Text;
};

// One attribute value: empty = NULL.
struct GpkgValue {
  std::optional<std::string> text;
  std::optional<long long> integer;
  std::optional<double> real;
};

struct GpkgPart {
  std::string building, id, role;
  double level = 0;
  int index = 0;
  int mass = -1;      // the part's mass (index within its building and level)
  std::string piece;  // body, layer or roof (docs/massing.md, "Masses")
  double z_min = 0, z_max = 0, volume = 0, convexity = 0, footprint_area = 0;
  bool grounded = false;
  MultiPolygon2 footprint;
};

class GpkgWriter {
 public:
  // `crs` as in the CityJSON metadata ("EPSG:7415", an OGC URL, or empty = undefined).
  // Throws mc::io::WriteError when the file cannot be created.
  GpkgWriter(const std::string& path, const std::string& crs, std::vector<GpkgColumn> building_columns);
  ~GpkgWriter();
  GpkgWriter(const GpkgWriter&) = delete;
  GpkgWriter& operator=(const GpkgWriter&) = delete;

  // `values` in the order of the building columns; an empty footprint writes a NULL geometry.
  void add_building(const MultiPolygon2& footprint, const std::vector<GpkgValue>& values);
  void add_part(const GpkgPart& part);
  // Commits the transaction, closes the file and renames it into place. Throws WriteError.
  void commit();

  const std::string& path() const { return path_; }

 private:
  struct Impl;
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc::io
