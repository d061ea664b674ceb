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
  // How many features next() will return, when the source knows before reading them (progress).
  virtual std::optional<size_t> feature_count() const { return std::nullopt; }
};

// A source that changes another's features as they are read (axis order, CRS): it owns the inner
// source and forwards what it does not change; the header starts as the inner one's.
class SourceFilter : public FeatureSource {
 public:
  explicit SourceFilter(std::unique_ptr<FeatureSource> in) : in_(std::move(in)), header_(in_->header()) {}
  const Header& header() const override { return header_; }
  const std::vector<std::string>& problems() const override { return in_->problems(); }
  std::string format() const override { return in_->format(); }
  std::optional<size_t> feature_count() const override { return in_->feature_count(); }

 protected:
  std::unique_ptr<FeatureSource> in_;
  Header header_;
};

// True for the CityGML extensions: .gml, .xml and their gzip-compressed forms (.gml.gz, .xml.gz).
bool is_citygml_path(const std::string& path);

// CityGML by extension (is_citygml_path), else CityJSON / CityJSONSeq ("-" = CityJSONSeq on
// stdin). Throws ReadError when the file cannot be opened or is not of its format.
// Geographic coordinates come longitude first, as CityJSON writes them: a file in a CRS whose
// axis order is latitude first (GML follows the CRS: EPSG:4326, 4979, 6697, ...) has its first
// two coordinates swapped as it is read.
std::unique_ptr<FeatureSource> open_feature_source(const std::string& path);

}  // namespace mc::io
