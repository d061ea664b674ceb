// Test-only OFF reader and access to the paper's sample buildings (io/ has the real reader;
// core tests must not depend on it). Accepts OFF/NOFF/COFF/... headers, comments, and the
// counts on the header line or the next one; vertex lines keep their first three numbers.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/polygon_mesh.hpp"

namespace mc::test {

inline PolygonMesh load_off(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  if (lines.empty() || lines[0].find("OFF") == std::string::npos)
    throw std::runtime_error("not OFF: " + path);
  std::istringstream header(lines[0].substr(lines[0].find("OFF") + 3));
  size_t nv = 0, nf = 0, next = 1;
  if (!(header >> nv >> nf)) {
    std::istringstream counts(lines.at(1));
    counts >> nv >> nf;
    next = 2;
  }
  PolygonMesh m;
  for (size_t i = 0; i < nv; ++i) {
    std::istringstream s(lines.at(next++));
    Vec3 v;
    s >> v.x >> v.y >> v.z;
    m.vertices.push_back(v);
  }
  for (size_t i = 0; i < nf; ++i) {
    std::istringstream s(lines.at(next++));
    size_t n = 0;
    s >> n;
    Polygon f;
    f.rings.emplace_back(n);
    for (auto& idx : f.rings[0]) s >> idx;
    m.faces.push_back(std::move(f));
  }
  return m;
}

inline std::filesystem::path samples_dir() {
  return std::filesystem::path(MC_SOURCE_DIR) / ".." / "shared" / "datasets" / "morphcut-samples";
}

struct Sample {
  std::string name;  // "sample11"
  std::filesystem::path off;
  std::map<std::string, double> config;  // numeric keys of NAME.off_config.json (may be empty)
  // numeric "key=value" pairs of NAME.off_param.txt: the parameters the paper's run actually
  // used (also for samples without a config) and its result counts, e.g. planar_region.
  std::map<std::string, double> used;
};

// Minimal "key": number extraction; enough for the flat sample configs.
inline std::map<std::string, double> read_numeric_config(const std::filesystem::path& p) {
  std::map<std::string, double> out;
  std::ifstream in(p);
  if (!in) return out;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  for (size_t q = s.find('"'); q != std::string::npos; q = s.find('"', q + 1)) {
    const size_t e = s.find('"', q + 1);
    if (e == std::string::npos) break;
    const size_t colon = s.find_first_not_of(" \t\r\n", e + 1);
    if (colon != std::string::npos && s[colon] == ':') {
      const char* start = s.c_str() + colon + 1;
      char* end = nullptr;
      const double v = std::strtod(start, &end);
      if (end != start) out[s.substr(q + 1, e - q - 1)] = v;
    }
    q = e;
  }
  return out;
}

inline std::map<std::string, double> read_param_txt(const std::filesystem::path& p) {
  std::map<std::string, double> out;
  std::ifstream in(p);
  std::string tok;
  while (in >> tok) {
    for (std::string item; !tok.empty();) {
      const size_t comma = tok.find(',');
      item = tok.substr(0, comma);
      tok = comma == std::string::npos ? "" : tok.substr(comma + 1);
      const size_t eq = item.find('=');
      if (eq == std::string::npos) continue;
      const std::string val = item.substr(eq + 1);
      char* end = nullptr;
      const double v = std::strtod(val.c_str(), &end);
      if (!val.empty() && end == val.c_str() + val.size()) out[item.substr(0, eq)] = v;
    }
  }
  return out;
}

// Every sample folder with an input mesh, sorted by name.
inline std::vector<Sample> samples() {
  std::vector<Sample> out;
  if (!std::filesystem::exists(samples_dir())) return out;
  for (const auto& dir : std::filesystem::directory_iterator(samples_dir())) {
    if (!dir.is_directory()) continue;
    for (const auto& f : std::filesystem::directory_iterator(dir.path())) {
      const std::string fn = f.path().filename().string();
      if (fn.size() > 4 && fn.ends_with(".off") && !fn.ends_with("_reconstruction.off")) {
        Sample s{dir.path().filename().string(), f.path(), {}, {}};
        s.config = read_numeric_config(f.path().string() + "_config.json");
        s.used = read_param_txt(f.path().string() + "_param.txt");
        out.push_back(std::move(s));
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Sample& a, const Sample& b) { return a.name < b.name; });
  return out;
}

// The preprocessing parameters of the paper's own run of a sample (NAME.off_param.txt, also
// present for the samples that ship no config); no Hausdorff measurement.
inline PreprocessParams paper_params(const Sample& s) {
  PreprocessParams p;
  p.cell_size = s.used.at("cell_size");
  p.dist_thresh = s.used.at("dist_thresh");
  p.max_distance = s.used.at("max_distance");
  p.max_angle_deg = s.used.at("max_angle");
  p.angle_thresh_deg = s.used.at("angle_thresh");
  p.min_region = static_cast<int>(s.used.at("min_region"));
  p.compute_hausdorff = false;
  return p;
}

}  // namespace mc::test
