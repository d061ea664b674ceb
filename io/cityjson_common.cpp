#include "io/cityjson_common.hpp"

#include <cmath>
#include <regex>

#include "io/errors.hpp"

namespace mc::io {

bool is_supported_version(const std::string& v) {
  // "2.0.1"-style patch versions are 2.0 files too (the spec keeps "2.0" in files).
  return v == "1.0" || v == "1.1" || v == "2.0" || v.rfind("2.0.", 0) == 0;
}

void check_version(const nlohmann::json& root, const std::string& source) {
  auto v = root.find("version");
  if (v == root.end())
    throw ReadError(source + ": missing \"version\" (supported CityJSON versions: 1.0, 1.1, 2.0)");
  if (!v->is_string())
    throw ReadError(source + ": \"version\" must be a string, got " + v->dump() +
                    " (supported CityJSON versions: 1.0, 1.1, 2.0)");
  if (!is_supported_version(v->get<std::string>()))
    throw ReadError(source + ": unsupported CityJSON version \"" + v->get<std::string>() +
                    "\" (supported: 1.0, 1.1, 2.0)");
}

Transform parse_transform(const nlohmann::json& root, const std::string& source) {
  Transform t;
  auto it = root.find("transform");
  if (it == root.end() || it->is_null()) return t;
  auto bad = [&](const std::string& why) { return ReadError(source + ": invalid \"transform\": " + why); };
  if (!it->is_object()) throw bad("not an object");
  auto three = [&](const char* name, bool nonzero) {
    auto m = it->find(name);
    if (m == it->end() || !m->is_array() || m->size() != 3)
      throw bad(std::string(name) + " must be 3 numbers");
    mc::Vec3 v;
    double* c[3] = {&v.x, &v.y, &v.z};
    for (int i = 0; i < 3; ++i) {
      const auto& e = (*m)[i];
      if (!e.is_number()) throw bad(std::string(name) + " must be 3 numbers");
      *c[i] = e.get<double>();
      if (!std::isfinite(*c[i]) || (nonzero && *c[i] == 0))
        throw bad(std::string(name) + " must be finite" + (nonzero ? " and non-zero" : ""));
    }
    return v;
  };
  t.scale = three("scale", true);
  t.translate = three("translate", false);
  t.present = true;
  return t;
}

std::string parse_crs(const nlohmann::json& root) {
  auto md = root.find("metadata");
  if (md == root.end() || !md->is_object()) return "";
  auto rs = md->find("referenceSystem");
  if (rs != md->end() && rs->is_string()) {
    // OGC URLs carry an EPSG version segment that is not always 0 (".../EPSG/6.12/3068").
    static const std::regex url(R"(/crs/EPSG/[^/]*/(\d+)\s*$)", std::regex::icase);
    static const std::regex urn(R"(EPSG:[^:]*:(\d+)\s*$)", std::regex::icase);
    static const std::regex plain(R"(^\s*EPSG:(\d+)\s*$)", std::regex::icase);
    std::smatch m;
    const std::string s = rs->get<std::string>();
    if (std::regex_search(s, m, url) || std::regex_search(s, m, urn) || std::regex_search(s, m, plain))
      return "EPSG:" + m[1].str();
    return "";
  }
  auto crs = md->find("crs");  // CityJSON 1.0: "crs": {"epsg": 7415}
  if (crs != md->end() && crs->is_object()) {
    auto e = crs->find("epsg");
    if (e != crs->end() && e->is_number_integer()) return "EPSG:" + std::to_string(e->get<long long>());
  }
  return "";
}

std::string lod_string(const nlohmann::json& lod) {
  if (lod.is_string()) return lod.get<std::string>();
  if (lod.is_number()) return lod.dump();
  return "";
}

bool nested_deeper_than(const std::string& text, int limit) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

}  // namespace mc::io
