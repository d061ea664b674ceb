// morphcut: MorphCut on one building mesh (OFF/OBJ), for reproducing the paper's samples.
//
//   morphcut preprocess IN.off [--config FILE] [--out DIR] [--timeout S]
//   morphcut decompose  IN.off [--config FILE] [--out DIR] [--threads N] [--timeout S] [--levels l1,l2,..]
//
// The configuration is a YAML file (config/lod.yaml layout) or the paper's JSON
// (`NAME.off_config.json`); without --config, `IN_config.json` beside the input is used when
// present (as the paper's samples ship), otherwise the defaults with automatic resolution.
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <future>
#include <map>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "config/config.hpp"
#include "config/paper_config.hpp"
#include "core/decompose.hpp"
#include "core/hausdorff.hpp"
#include "core/preprocess.hpp"
#include "core/soup.hpp"
#include "io/atomic_file.hpp"
#include "io/off_obj.hpp"
#include "report/level_json.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

int usage(const char* msg = nullptr) {
  if (msg) std::cerr << "morphcut: " << msg << "\n";
  std::cerr << "usage:\n"
               "  morphcut preprocess IN.off|IN.obj [--config FILE] [--out DIR] [--timeout S]\n"
               "  morphcut decompose  IN.off|IN.obj [--config FILE] [--out DIR] [--threads N] [--timeout S]\n"
               "                      [--levels l1,l2,...] [--set KEY=VALUE ...]\n"
               "  morphcut hausdorff  A.off B.off [--offset x,y,z]   (B translated by the offset)\n"
               "Writes DIR/<stem>_singleton.off and, for decompose, DIR/<stem>_lod_<l>.off per level and\n"
               "DIR/<stem>.morphcut.json. --config takes YAML (config/lod.yaml) or the paper's JSON;\n"
               "default: <IN>_config.json beside the input if present. --set overrides one key of the\n"
               "effective configuration after it is loaded (YAML path, e.g. decompose.max_candidates=0).\n"
               "Exit codes: 0 ok, 1 partial or failed, 2 usage or I/O error.\n";
  return 2;
}

void write_text(const std::string& path, const std::string& text) {
  mc::io::AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

// One OFF for a level: every part's faces, one colour per part (hue spread like the paper's).
void write_level_off(const std::string& path, const mc::Preprocessed& pre, const mc::LevelResult& level) {
  mc::PolygonMesh all;
  std::vector<mc::io::Rgb> colours;
  const size_t n = level.parts.size();
  for (size_t i = 0; i < n; ++i) {
    const mc::PolygonMesh m = mc::part_mesh(pre, level.parts[i]);
    const uint32_t base = static_cast<uint32_t>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), m.vertices.begin(), m.vertices.end());
    const double hue = 360.0 * i / std::max<size_t>(1, n);
    const double x = 1 - std::abs(std::fmod(hue / 60.0, 2) - 1);
    double r = 0, g = 0, b = 0;
    const int sector = static_cast<int>(hue / 60) % 6;
    if (sector == 0) {
      r = 1;
      g = x;
    } else if (sector == 1) {
      r = x;
      g = 1;
    } else if (sector == 2) {
      g = 1;
      b = x;
    } else if (sector == 3) {
      g = x;
      b = 1;
    } else if (sector == 4) {
      r = x;
      b = 1;
    } else {
      r = 1;
      b = x;
    }
    for (mc::Polygon f : m.faces) {
      for (auto& ring : f.rings)
        for (auto& v : ring) v += base;
      f.semantic = -1;
      all.faces.push_back(std::move(f));
      colours.push_back({uint8_t(255 * r), uint8_t(255 * g), uint8_t(255 * b)});
    }
  }
  mc::io::write_off(path, all, colours);
}

// `--set decompose.split_chains=false`: edits the effective configuration (as JSON, the YAML
// layout) and reloads it, so every override gets the loader's type and range checks.
mc::Params apply_sets(const mc::Params& params, const std::vector<std::string>& sets) {
  nlohmann::json cfg = mc::effective_config_json(params, mc::RunConfig{});
  for (const std::string& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("--set wants KEY=VALUE, got " + s);
    const std::string key = s.substr(0, eq), text = s.substr(eq + 1);
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    if (value.is_discarded()) value = text;
    nlohmann::json* node = &cfg;
    std::stringstream path(key);
    for (std::string part; std::getline(path, part, '.');) node = &(*node)[part];
    *node = value;
  }
  return mc::load_config_string(cfg.dump(), "--set").params;
}

std::string lod_name(double l) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", l);
  return buf;
}

// `morphcut hausdorff A B [--offset x,y,z]`: the symmetric Hausdorff distance between two meshes
// (B translated by the offset first), measured exactly as preprocessing measures input <-> cell;
// e.g. the paper's own singleton cell (centred: offset = its origional_center) against the input.
int hausdorff_main(int argc, char** argv) {
  if (argc < 4) return usage("hausdorff needs two meshes");
  auto read = [](const std::string& p) {
    return p.size() > 4 && p.substr(p.size() - 4) == ".obj" ? mc::io::read_obj(p) : mc::io::read_off(p);
  };
  mc::PolygonMesh a = read(argv[2]), b = read(argv[3]);
  if (argc >= 6 && std::string(argv[4]) == "--offset") {
    mc::Vec3 o{};
    if (std::sscanf(argv[5], "%lf,%lf,%lf", &o.x, &o.y, &o.z) != 3) return usage("--offset wants x,y,z");
    mc::translate(b, o);
  }
  const mc::TriangleSoup ta = mc::triangulate(a), tb = mc::triangulate(b);
  const mc::HausdorffResult h = mc::hausdorff(ta, tb, 0);
  json r{{"a", argv[2]},
         {"b", argv[3]},
         {"a_to_b", h.a_to_b},
         {"b_to_a", h.b_to_a},
         {"symmetric", h.symmetric},
         {"mean_a_to_b", h.mean_a_to_b},
         {"mean_b_to_a", h.mean_b_to_a},
         {"mean_symmetric", h.mean_symmetric}};
  std::cout << r.dump() << "\n";
  return 0;
}

struct Options {
  std::string cmd, input, config, out = ".", levels;
  std::vector<std::string> sets;
  double timeout = -1;
  int threads = 0;
};

// The command line; nullopt after a usage error (printed).
std::optional<Options> parse(int argc, char** argv) {
  Options o;
  o.cmd = argv[1];
  o.input = argv[2];
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--config") o.config = value();
      else if (a == "--out") o.out = value();
      else if (a == "--timeout") o.timeout = std::stod(value());
      else if (a == "--threads") o.threads = std::stoi(value());
      else if (a == "--levels") o.levels = value();
      else if (a == "--set") o.sets.push_back(value());
      else {
        usage(("unknown option " + a).c_str());
        return std::nullopt;
      }
    } catch (const std::exception& e) {
      usage(e.what());
      return std::nullopt;
    }
  }
  return o;
}

// The configuration: --config (YAML or the paper's JSON), else <IN>_config.json beside the input,
// else the defaults; then --set, --levels and --timeout. Throws on a bad file or value.
mc::Params load_params(Options& o) {
  mc::Params params;
  if (o.config.empty() && fs::exists(o.input + "_config.json")) o.config = o.input + "_config.json";
  if (!o.config.empty())
    params = o.config.size() > 5 && o.config.substr(o.config.size() - 5) == ".json"
                 ? mc::load_paper_config(o.config)
                 : mc::load_config_file(o.config).params;
  if (!o.sets.empty()) params = apply_sets(params, o.sets);
  if (!o.levels.empty()) {
    params.dec.levels.clear();
    std::stringstream ss(o.levels);
    for (std::string t; std::getline(ss, t, ',');) params.dec.levels.push_back(std::stod(t));
  }
  if (o.timeout >= 0) params.timeout_s = o.timeout;
  return params;
}

// The singleton cell's figures; the fingerprint of the complex (bit-exact vertices and interior
// cells) is for determinism checks.
json preprocess_json(const mc::Preprocessed& pre, const std::vector<std::string>& problems) {
  json j = {{"seconds", pre.seconds},
            {"planes", pre.regions},
            {"hole_planes", pre.hole_planes},
            {"anchored_planes", pre.anchored_planes},
            {"cells", pre.cells},
            {"interior_cells", pre.inside_cells},
            {"components", pre.components.size()},
            {"closed", pre.closed},
            {"manifold", pre.manifold},
            {"cell_size", pre.cell_size},
            {"dist_thresh", pre.dist},
            {"up_axis", pre.up_axis == 1 ? "y" : "z"},
            {"oracle_points", pre.oracle_points},
            {"fast_path", pre.fast_path},
            {"fast_path_reason", pre.fast_path_reason},
            {"problems", problems}};
  double volume = 0;
  for (const auto& c : pre.components) volume += c.volume;
  uint64_t h = 1469598103934665603ULL;
  auto mixin = [&h](uint64_t x) { h = (h ^ x) * 1099511628211ULL; };
  for (size_t v = 0; v < pre.complex->num_vertices(); ++v) {
    const mc::Vec3& q = pre.complex->point(static_cast<uint32_t>(v));
    uint64_t b[3];
    std::memcpy(b, &q, sizeof b);
    mixin(b[0]);
    mixin(b[1]);
    mixin(b[2]);
  }
  for (const auto& c : pre.components)
    for (uint32_t x : c.cells) mixin(x);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  j["fingerprint"] = buf;
  j["volume"] = volume;
  return j;
}

// The cell's fidelity (measured beside the levels), also reported when they fail.
void add_fidelity(json& pre_json, const mc::Preprocessed& pre) {
  pre_json["hausdorff"] = pre.hausdorff;
  pre_json["hausdorff_input_to_cell"] = pre.hausdorff_in_to_cell;
  pre_json["hausdorff_cell_to_input"] = pre.hausdorff_cell_to_in;
  pre_json["mean_distance"] = pre.mean_distance;
  pre_json["mean_distance_cell_to_input"] = pre.mean_distance_cell_to_in;
  pre_json["mean_distance_symmetric"] = pre.mean_distance_symmetric;
}

// One OFF per level, written at once (each level's parts only read the complex); two levels with
// one file name leave the later level's, as one after the other did. The first error in level
// order is the one reported.
void write_levels(const std::string& dir, const std::string& stem, const mc::Preprocessed& pre,
                  const mc::Decomposition& d) {
  std::map<std::string, size_t> last_of_path;
  for (size_t i = 0; i < d.levels.size(); ++i)
    last_of_path[dir + "/" + stem + "_lod_" + lod_name(d.levels[i].lod) + ".off"] = i;
  const std::vector<std::pair<std::string, size_t>> files(last_of_path.begin(), last_of_path.end());
  std::vector<std::exception_ptr> errors(d.levels.size());
  tbb::parallel_for(size_t(0), files.size(), [&](size_t k) {
    const auto& [path, i] = files[k];
    try {
      write_level_off(path, pre, d.levels[i]);
    } catch (...) { errors[i] = std::current_exception(); }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// Each level in the run report's schema (report/level_json.hpp), with its parts.
json levels_json(const mc::Decomposition& d) {
  json levels = json::array();
  for (size_t i = 0; i < d.levels.size(); ++i) {
    const mc::LevelResult& level = d.levels[i];
    json parts = json::array();
    for (const auto& p : level.parts)
      parts.push_back({{"volume", p.volume},
                       {"hull_volume", p.hull_volume},
                       {"convexity", p.convexity},
                       {"neighbours", p.neighbours}});
    json lj = json::parse(mc::report::level_json(mc::report::level_outcome(level, i)).dump());
    lj["part_list"] = std::move(parts);
    levels.push_back(std::move(lj));
  }
  return levels;
}

// Preprocessing and (for decompose) the levels of one mesh, with their files; the report's
// status and reason say what went wrong.
void run(const Options& o, const mc::Params& params, mc::Clock::time_point deadline, json& report) {
  const std::string stem = fs::path(o.input).stem().string();
  fs::create_directories(o.out);
  std::vector<std::string> problems;
  const bool obj = o.input.size() > 4 && o.input.substr(o.input.size() - 4) == ".obj";
  const mc::PolygonMesh mesh =
      obj ? mc::io::read_obj(o.input, &problems) : mc::io::read_off(o.input, &problems);
  // The fidelity measure runs beside the levels (decompose_measuring_fidelity).
  mc::Preprocessed pre = mc::preprocess(mesh, params.pre, deadline, std::numeric_limits<double>::quiet_NaN(),
                                        /*defer_fidelity=*/true);
  problems.insert(problems.end(), pre.problems.begin(), pre.problems.end());
  // The singleton cell's surface is taken before the levels refine its cells, and written on a
  // thread of its own beside them (its file syncs wait on the disk, not on a core). It is
  // written whatever the levels do; a write error is reported once they are done.
  const mc::PolygonMesh singleton = mc::singleton_mesh(pre);
  std::future<void> singleton_written = std::async(
      std::launch::async, [&] { mc::io::write_off(o.out + "/" + stem + "_singleton.off", singleton); });
  report["preprocess"] = preprocess_json(pre, problems);
  if (pre.truncated) {
    report["status"] = "partial";
    report["reason"] = "carving stopped by the deadline or the cell limit";
  }
  mc::DecomposeParams dec = params.dec;
  if (o.cmd == "preprocess") dec.levels.clear();  // concave edges of the singleton cell (no search)
  mc::Decomposition d;
  try {
    d = mc::decompose_measuring_fidelity(pre, dec, deadline);
  } catch (...) {
    add_fidelity(report["preprocess"], pre);
    throw;
  }
  add_fidelity(report["preprocess"], pre);
  report["preprocess"]["concave_edges"] = d.concave_edges;
  if (o.cmd == "decompose") {
    write_levels(o.out, stem, pre, d);
    report["levels"] = levels_json(d);
    if (d.partial) {
      report["status"] = "partial";
      report["reason"] = d.reason;
    }
  }
  singleton_written.get();  // (its error, if any)
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "hausdorff") return hausdorff_main(argc, argv);
  if (argc < 3) return usage();
  if (std::string(argv[1]) != "preprocess" && std::string(argv[1]) != "decompose")
    return usage("unknown command");
  std::optional<Options> o = parse(argc, argv);
  if (!o) return 2;
  mc::Params params;
  try {
    params = load_params(*o);
  } catch (const std::exception& e) {
    std::cerr << "morphcut: config: " << e.what() << "\n";
    return 2;
  }
  std::unique_ptr<tbb::global_control> gc;
  if (o->threads > 0)
    gc = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o->threads);
  const auto t0 = mc::Clock::now();
  const auto deadline = params.timeout_s > 0 ? t0 + std::chrono::duration_cast<mc::Clock::duration>(
                                                        std::chrono::duration<double>(params.timeout_s))
                                             : mc::Clock::time_point::max();
  json report{{"input", o->input}, {"status", "ok"}, {"reason", nullptr}};
  try {
    run(*o, params, deadline, report);
  } catch (const std::exception& e) {
    report["status"] = "failed";
    report["reason"] = e.what();
  }
  report["seconds"] = std::chrono::duration<double>(mc::Clock::now() - t0).count();
  try {
    write_text(o->out + "/" + fs::path(o->input).stem().string() + ".morphcut.json", report.dump(2) + "\n");
  } catch (const std::exception& e) {
    std::cerr << "morphcut: cannot write the report: " << e.what() << "\n";
    return 2;
  }
  std::cout << report.dump(2) << "\n";
  return report["status"] != "ok" ? 1 : 0;
}
