#include "io/feature_source.hpp"

#include <algorithm>
#include <cctype>

#include "io/cityjson_reader.hpp"
#include "io/citygml_reader.hpp"

namespace mc::io {

namespace {

// The CityJSON reader behind the FeatureSource interface (it keeps its own concrete API).
class CityJsonSource : public FeatureSource {
 public:
  explicit CityJsonSource(const std::string& path) : reader_(path) {}
  const Header& header() const override { return reader_.header(); }
  bool next(Feature& out) override { return reader_.next(out); }
  const std::vector<std::string>& problems() const override { return reader_.problems(); }
  std::string format() const override { return reader_.is_sequence() ? "CityJSONSeq" : "CityJSON"; }
  std::optional<size_t> feature_count() const override { return reader_.feature_count(); }

 private:
  CityJsonReader reader_;
};

bool ends_with_icase(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                    [](char ext, char c) { return ext == std::tolower(static_cast<unsigned char>(c)); });
}

}  // namespace

bool is_citygml_path(const std::string& path) {
  for (const char* ext : {".gml", ".xml", ".gml.gz", ".xml.gz"})
    if (ends_with_icase(path, ext)) return true;
  return false;
}

std::unique_ptr<FeatureSource> open_feature_source(const std::string& path) {
  if (is_citygml_path(path)) return std::make_unique<CityGmlReader>(path);
  return std::make_unique<CityJsonSource>(path);
}

}  // namespace mc::io
