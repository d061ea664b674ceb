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

// Latitude-first coordinates turned longitude first (x = easting-like, y = northing-like).
class LongitudeFirstSource : public SourceFilter {
 public:
  explicit LongitudeFirstSource(std::unique_ptr<FeatureSource> in) : SourceFilter(std::move(in)) {
    header_.coords.lat_first = false;
    if (auto t = header_.root.find("transform"); t != header_.root.end() && t->is_object())
      for (const char* k : {"scale", "translate"})
        if (auto v = t->find(k); v != t->end() && v->is_array() && v->size() == 3)
          std::swap((*v)[0], (*v)[1]);
    header_.coords_note = "the file's coordinates are latitude first (" + header_.crs +
                          "): they are written longitude first, as CityJSON writes geographic coordinates";
  }
  bool next(Feature& out) override {
    if (!in_->next(out)) return false;
    for (mc::Vec3& v : out.vertices) std::swap(v.x, v.y);
    return true;
  }
};

}  // namespace

bool is_citygml_path(const std::string& path) {
  for (const char* ext : {".gml", ".xml", ".gml.gz", ".xml.gz"})
    if (ends_with_icase(path, ext)) return true;
  return false;
}

std::unique_ptr<FeatureSource> open_feature_source(const std::string& path) {
  std::unique_ptr<FeatureSource> s;
  if (is_citygml_path(path)) s = std::make_unique<CityGmlReader>(path);
  else s = std::make_unique<CityJsonSource>(path);
  if (s->header().coords.geographic() && s->header().coords.lat_first)
    s = std::make_unique<LongitudeFirstSource>(std::move(s));
  return s;
}

}  // namespace mc::io
