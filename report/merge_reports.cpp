#include "report/merge_reports.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/errors.hpp"
#include "io/scratch_file.hpp"
#include "report/outcome.hpp"
#include "io/sha256.hpp"
#include "config/config.hpp"

namespace mc::report {

using namespace mc::massing;

using ojson = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

std::string strip_suffix(const std::string& name, std::initializer_list<std::string_view> suffixes) {
  for (std::string_view ext : suffixes)
    if (name.ends_with(ext) && name.size() > ext.size()) return name.substr(0, name.size() - ext.size());
  return name;
}

bool read_text(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) return false;
  out = s.str();
  return true;
}

std::string parent_dir(const std::string& path) {
  const std::string d = fs::path(path).parent_path().string();
  return d.empty() ? "." : d;
}

// CSV records (RFC 4180: a quoted field may hold line breaks), without their line endings.
std::vector<std::string_view> csv_records(std::string_view text) {
  std::vector<std::string_view> out;
  size_t start = 0;
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"') quoted = !quoted;
    else if (text[i] == '\n' && !quoted) {
      size_t end = i;
      if (end > start && text[end - 1] == '\r') --end;
      out.push_back(text.substr(start, end - start));
      start = i + 1;
    }
  }
  if (start < text.size()) out.push_back(text.substr(start));
  return out;
}

std::vector<std::string> csv_fields(std::string_view record) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < record.size(); ++i) {
    const char c = record[i];
    if (quoted) {
      if (c == '"' && i + 1 < record.size() && record[i + 1] == '"') fields.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else fields.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// The settings that shape results; worker threads and friends may differ between array tasks.
ojson result_config(const ojson& config) { return mc::outputs_config_json(config); }

const ojson& member(const ojson& j, const char* key) {
  static const ojson null_value;
  if (!j.is_object()) return null_value;
  auto it = j.find(key);
  return it == j.end() ? null_value : *it;
}

size_t count_of(const ojson& j) {
  return j.is_number_unsigned() || j.is_number_integer() ? j.get<size_t>() : 0;
}

void copy_spool(mc::io::ScratchFile& spool, std::ostream& o) {
  std::vector<char> buf(1 << 20);
  for (uint64_t at = 0; at < spool.size(); at += buf.size()) {
    const size_t n = static_cast<size_t>(std::min<uint64_t>(buf.size(), spool.size() - at));
    spool.read_at(at, buf.data(), n);
    o.write(buf.data(), static_cast<std::streamsize>(n));
  }
}

}  // namespace

std::string tile_name_of_report(const std::string& report_path) {
  return strip_suffix(fs::path(report_path).filename().string(),
                      {".morphcut.report.json", ".report.json", ".json"});
}

std::string csv_beside_report(const std::string& report_path) {
  if (!report_path.ends_with(".morphcut.report.json")) return {};
  return report_path.substr(0, report_path.size() - std::string_view(".report.json").size()) + ".csv";
}

std::string input_stem(const std::string& input_path) {
  if (input_path == "-") return "stdin";
  return strip_suffix(fs::path(input_path).filename().string(),
                      {".city.jsonl", ".city.json", ".jsonl", ".json"});
}

namespace {

// What the merge accumulates over the tiles: the merged report's parts and its totals.
struct Merge {
  const MergeOptions& opt;
  MergeResult res;
  std::unique_ptr<mc::io::AtomicFile> report_file, csv_file;
  std::unique_ptr<mc::io::ScratchFile> entries, csv_rows;  // building entries and CSV rows, spooled
  size_t entry_count = 0;
  std::vector<std::string> columns;                    // merged CSV header
  std::vector<std::vector<std::string>> tile_columns;  // each tile's CSV header
  ojson tiles = ojson::array(), missing = ojson::array();
  std::map<std::string, std::vector<std::string>> seen;  // building id -> tiles (ids only)
  std::string ref_version, ref_tile;
  ojson ref_config;
  double wall = 0;
  size_t cache_hits = 0, cache_misses = 0;
  bool any_cache = false;
  explicit Merge(const MergeOptions& o) : opt(o) {}
};

// Outputs first: a bad output path fails before anything is read.
void open_outputs(Merge& m) {
  try {
    m.report_file = std::make_unique<mc::io::AtomicFile>(m.opt.report_out);
    if (!m.opt.csv_out.empty()) m.csv_file = std::make_unique<mc::io::AtomicFile>(m.opt.csv_out);
  } catch (const std::exception& e) {
    throw mc::io::WriteError(std::string(m.report_file ? m.opt.csv_out : m.opt.report_out) + ": " + e.what());
  }
  m.entries = std::make_unique<mc::io::ScratchFile>(parent_dir(m.opt.report_out));
}

// CSV columns: the union over all tiles, in first-seen order (headers only are read here).
void read_csv_headers(Merge& m) {
  m.tile_columns.resize(m.opt.tiles.size());
  if (m.csv_file)
    for (size_t i = 0; i < m.opt.tiles.size(); ++i) {
      std::ifstream in(m.opt.tiles[i].csv, std::ios::binary);
      std::string header;
      if (m.opt.tiles[i].csv.empty() || !in || !std::getline(in, header)) continue;
      if (!header.empty() && header.back() == '\r') header.pop_back();
      m.tile_columns[i] = csv_fields(header);
      for (const auto& c : m.tile_columns[i])
        if (std::find(m.columns.begin(), m.columns.end(), c) == m.columns.end()) m.columns.push_back(c);
    }
  m.csv_rows = std::make_unique<mc::io::ScratchFile>(parent_dir(m.opt.report_out));
}

// A tile's report parsed, or why it cannot be merged.
std::string read_tile_report(const TileReport& t, std::string& text, ojson& doc) {
  if (!fs::exists(t.report)) return "report not found";
  if (!read_text(t.report, text)) return "report cannot be read";
  try {
    doc = ojson::parse(text);
    if (!doc.is_object() || !member(doc, "buildings").is_array()) return "not a morphcut-city run report";
  } catch (const std::exception& e) { return std::string("report is not valid JSON (") + e.what() + ")"; }
  return "";
}

// The tile's summary line, with any version or config that differs from the first tile's.
ojson tile_summary(Merge& m, const TileReport& t, const std::string& text, const ojson& doc) {
  const std::string version =
      member(doc, "version").is_string() ? member(doc, "version").get<std::string>() : "";
  const ojson config = result_config(member(doc, "config"));
  std::vector<std::string> mismatch;
  if (m.ref_tile.empty()) {
    m.ref_tile = t.name, m.ref_version = version, m.ref_config = config;
  } else {
    if (version != m.ref_version) {
      mismatch.push_back("version");
      m.res.warnings.push_back("tile " + t.name + ": tool version " + version + " differs from " +
                               m.ref_version + " (tile " + m.ref_tile + ")");
    }
    if (config != m.ref_config) {
      mismatch.push_back("config");
      m.res.warnings.push_back("tile " + t.name + ": effective config differs from tile " + m.ref_tile +
                               "'s (see tiles[].config_sha256)");
    }
  }
  const ojson& input = member(doc, "input");
  const ojson& cache = member(doc, "cache");
  ojson s = {{"tile", t.name},
             {"report", t.report},
             {"report_sha256", mc::io::sha256_hex(text)},
             {"input", member(input, "path")},
             {"input_sha256", member(input, "sha256")},
             {"outputs", member(doc, "outputs")},  // the tile's city, one city per level, CSV
             {"version", version},
             {"config_sha256", mc::io::sha256_hex(config.dump())},
             {"building_count", member(doc, "building_count")},
             {"counts", member(doc, "counts")},
             {"wall_seconds", member(doc, "wall_seconds")},
             {"cache", cache}};
  if (!mismatch.empty()) s["mismatch"] = mismatch;
  if (member(doc, "wall_seconds").is_number()) m.wall += member(doc, "wall_seconds").get<double>();
  if (cache.is_object()) {
    m.any_cache = true;
    m.cache_hits += count_of(member(cache, "hits"));
    m.cache_misses += count_of(member(cache, "misses"));
  }
  return s;
}

// Building entries, with the tile first.
void spool_buildings(Merge& m, const TileReport& t, const ojson& doc) {
  const ojson& buildings = doc["buildings"];
  for (const ojson& b : buildings) {
    ojson e = {{"tile", t.name}};
    for (auto it = b.begin(); it != b.end(); ++it) e[it.key()] = it.value();
    const ojson& status = member(b, "status");
    if (status.is_string()) ++m.res.counts[status.get<std::string>()];
    if (member(b, "id").is_string()) m.seen[member(b, "id").get<std::string>()].push_back(t.name);
    m.entries->append(std::string(m.entry_count++ ? ",\n    " : "\n    ") + e.dump());
  }
  m.res.buildings += buildings.size();
  if (member(doc, "building_count").is_number() &&
      count_of(member(doc, "building_count")) != buildings.size())
    m.res.warnings.push_back("tile " + t.name + ": building_count " + member(doc, "building_count").dump() +
                             " but " + std::to_string(buildings.size()) + " entries");
}

// CSV rows, with the tile first; rows of a tile with other columns are mapped by name.
void spool_csv_rows(Merge& m, size_t i, size_t building_entries, ojson& s) {
  const TileReport& t = m.opt.tiles[i];
  std::string csv_text;
  if (t.csv.empty() || !read_text(t.csv, csv_text) || m.tile_columns[i].empty()) {
    m.res.csv_incomplete = true;
    m.res.warnings.push_back("tile " + t.name + ": summary CSV " +
                             (t.csv.empty() ? "not given" : t.csv + " missing"));
    s["csv"] = nullptr;
    return;
  }
  const auto records = csv_records(csv_text);
  const auto& own = m.tile_columns[i];
  const bool same = own == m.columns;
  if (!same) m.res.warnings.push_back("tile " + t.name + ": CSV columns differ from the merged header");
  const std::string tile_field = mc::io::csv_escape(t.name);
  std::ostringstream csv_body;  // this tile's rows
  size_t rows = 0;
  for (size_t r = 1; r < records.size(); ++r) {
    if (records[r].empty()) continue;
    csv_body << tile_field << ',';
    if (same) {
      csv_body << records[r];
    } else {
      const auto fields = csv_fields(records[r]);
      for (size_t c = 0; c < m.columns.size(); ++c) {
        const auto at = std::find(own.begin(), own.end(), m.columns[c]);
        const size_t k = static_cast<size_t>(at - own.begin());
        if (c) csv_body << ',';
        if (at != own.end() && k < fields.size()) csv_body << mc::io::csv_escape(fields[k]);
      }
    }
    csv_body << "\r\n";
    ++rows;
  }
  m.csv_rows->append(csv_body.str());
  m.res.csv_rows += rows;
  s["csv"] = t.csv;
  s["csv_rows"] = rows;
  if (rows != building_entries)
    m.res.warnings.push_back("tile " + t.name + ": " + std::to_string(rows) + " CSV rows but " +
                             std::to_string(building_entries) + " report entries");
}

// The merged report (head, then the spooled entries) and CSV, committed together.
void write_outputs(Merge& m) {
  MergeResult& res = m.res;
  ojson duplicates = ojson::array();
  for (const auto& [id, where] : m.seen)
    if (where.size() > 1) duplicates.push_back({{"id", id}, {"tiles", where}});
  res.duplicate_ids = duplicates.size();

  ojson counts = ojson::object();
  for (const auto& [status, n] : res.counts) counts[status] = n;
  ojson head = {
      {"tool", "morphcut-city merge-reports"},
      {"version", MC_VERSION},
      {"tiles", std::move(m.tiles)},
      {"missing_tiles", std::move(m.missing)},
      {"totals",
       {{"tiles", res.tiles},
        {"merged", res.merged},
        {"missing", res.tiles - res.merged},
        {"building_count", res.buildings},
        {"counts", counts},
        {"duplicate_ids", res.duplicate_ids},
        {"wall_seconds", m.wall},
        {"cache", m.any_cache ? ojson{{"hits", m.cache_hits}, {"misses", m.cache_misses}} : ojson(nullptr)},
        {"csv_rows", m.csv_file ? ojson(res.csv_rows) : ojson(nullptr)}}},
      {"duplicates", std::move(duplicates)},
      {"warnings", res.warnings}};

  std::ostream& o = m.report_file->stream();
  std::string text = head.dump(2);
  text.pop_back();  // the closing brace: "buildings" follows
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  o << text << ",\n  \"buildings\": [";
  copy_spool(*m.entries, o);
  o << (m.entry_count ? "\n  ]\n}\n" : "]\n}\n");

  if (m.csv_file) {
    std::ostream& c = m.csv_file->stream();
    c << "tile";
    for (const auto& col : m.columns) c << ',' << mc::io::csv_escape(col);
    c << "\r\n";
    copy_spool(*m.csv_rows, c);
  }
  try {
    m.report_file->commit();
    if (m.csv_file) m.csv_file->commit();
  } catch (const std::exception& e) { throw mc::io::WriteError(std::string("merged outputs: ") + e.what()); }
}

}  // namespace

MergeResult merge_reports(const MergeOptions& opt) {
  Merge m(opt);
  m.res.tiles = opt.tiles.size();
  for (const char* s : kStatuses) m.res.counts[s] = 0;
  open_outputs(m);
  read_csv_headers(m);
  for (size_t i = 0; i < opt.tiles.size(); ++i) {
    const TileReport& t = opt.tiles[i];
    std::string text;
    ojson doc;
    if (const std::string why = read_tile_report(t, text, doc); !why.empty()) {
      m.missing.push_back({{"tile", t.name}, {"report", t.report}, {"reason", why}});
      m.res.missing.push_back(t.name + ": " + why);
      continue;
    }
    ++m.res.merged;
    ojson s = tile_summary(m, t, text, doc);
    spool_buildings(m, t, doc);
    if (m.csv_file) spool_csv_rows(m, i, doc["buildings"].size(), s);
    m.tiles.push_back(std::move(s));
  }
  write_outputs(m);
  return m.res;
}

}  // namespace mc::report
