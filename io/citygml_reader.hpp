// Streaming CityGML 1.0 / 2.0 / 3.0 reader: one Building (with its BuildingParts) at a time as a
// CityJSON 2.0 Feature. A libxml2 pull parser walks the file; only one building's subtree is
// ever expanded in memory, so memory does not grow with the file (gzip input is read directly).
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/feature_source.hpp"

namespace mc::io {

class CityGmlReader : public FeatureSource {
 public:
  // Reads the file once quickly (citygml_prescan: the building count, xlinks between buildings;
  // a second time only when there are such xlinks), then up to the first building to fill the
  // header (CRS, transform). Throws ReadError when the file cannot be opened, is not well-formed
  // XML (or declares entities), or its root is not a CityGML CityModel.
  explicit CityGmlReader(const std::string& path);
  ~CityGmlReader() override;
  CityGmlReader(const CityGmlReader&) = delete;
  CityGmlReader& operator=(const CityGmlReader&) = delete;

  // Version "2.0", metadata.referenceSystem from the srsName of the envelope (or of the first
  // building), a millimetre "transform" anchored at the envelope's (or first building's) corner.
  const Header& header() const override;
  // Throws ReadError at the first XML error (everything before it has been returned).
  bool next(Feature& out) override;
  // After the end: how many city objects of other types were skipped, srsName disagreements, ...
  const std::vector<std::string>& problems() const override;
  std::string format() const override;  // "CityGML 1.0", "CityGML 2.0" or "CityGML 3.0"
  // The number of buildings next() hands out, from the first pass; nullopt when that pass met an
  // XML error (then next() throws at it).
  std::optional<size_t> feature_count() const override;

  // City objects that are not buildings (skipped), by element name; complete at the end.
  const std::map<std::string, size_t>& skipped_objects() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc::io
