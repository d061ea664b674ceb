// What the city pipeline reads from: a stream of Features (one building with its parts) and a
// CityJSON header, whatever the input format.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/cityjson_types.hpp"
#include "io/errors.hpp"

namespace mc::io {

class FeatureSource {
 public:
  virtual ~FeatureSource() = default;
  // The CityJSON header the output is written with.
  virtual const Header& header() const = 0;
  // The next feature in file order; false at the end. Throws ReadError for file-level failures.
  virtual bool next(Feature& out) = 0;
  // Problems not attributable to one feature (complete once next() has returned false).
  virtual const std::vector<std::string>& problems() const = 0;
  // "CityJSON", "CityJSONSeq", "CityGML 1.0", "CityGML 2.0", "CityGML 3.0".
  virtual std::string format() const = 0;
  // How many features next() hands out, when the source knows it before reading them (a
  // progress estimate); nullopt when it does not.
  virtual std::optional<size_t> building_count() const { return std::nullopt; }
};

// True for the CityGML extensions: .gml, .xml and their gzip-compressed forms (.gml.gz, .xml.gz).
bool is_citygml_path(const std::string& path);

// CityGML by extension (is_citygml_path), else CityJSON / CityJSONSeq ("-" = CityJSONSeq on
// stdin). Throws ReadError when the file cannot be opened or is not of its format.
std::unique_ptr<FeatureSource> open_feature_source(const std::string& path);

}  // namespace mc::io
