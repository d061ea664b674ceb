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

MergeResult merge_reports(const MergeOptions& opt) {
  MergeResult res;
  res.tiles = opt.tiles.size();
  for (const char* s : kStatuses) res.counts[s] = 0;

  // Outputs first: a bad output path fails before anything is read.
  std::unique_ptr<mc::io::AtomicFile> report_file, csv_file;
  try {
    report_file = std::make_unique<mc::io::AtomicFile>(opt.report_out);
    if (!opt.csv_out.empty()) csv_file = std::make_unique<mc::io::AtomicFile>(opt.csv_out);
  } catch (const std::exception& e) {
    throw mc::io::WriteError(std::string(report_file ? opt.csv_out : opt.report_out) + ": " + e.what());
  }
  mc::io::ScratchFile entries(parent_dir(opt.report_out));  // building entries, spooled
  size_t entry_count = 0;

  // CSV columns: the union over all tiles, in first-seen order (headers only are read here).
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> tile_columns(opt.tiles.size());
  if (csv_file)
    for (size_t i = 0; i < opt.tiles.size(); ++i) {
      std::ifstream in(opt.tiles[i].csv, std::ios::binary);
      std::string header;
      if (opt.tiles[i].csv.empty() || !in || !std::getline(in, header)) continue;
      if (!header.empty() && header.back() == '\r') header.pop_back();
      tile_columns[i] = csv_fields(header);
      for (const auto& c : tile_columns[i])
        if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
    }
  mc::io::ScratchFile csv_rows(parent_dir(opt.report_out));  // merged CSV rows, spooled

  ojson tiles = ojson::array(), missing = ojson::array();
  std::map<std::string, std::vector<std::string>> seen;  // building id -> tiles (ids only)
  std::string ref_version, ref_tile;
  ojson ref_config;
  double wall = 0;
  size_t cache_hits = 0, cache_misses = 0;
  bool any_cache = false;

  for (size_t i = 0; i < opt.tiles.size(); ++i) {
    const TileReport& t = opt.tiles[i];
    std::string text;
    ojson doc;
    std::string why;
    if (!fs::exists(t.report)) {
      why = "report not found";
    } else if (!read_text(t.report, text)) {
      why = "report cannot be read";
    } else {
      try {
        doc = ojson::parse(text);
        if (!doc.is_object() || !member(doc, "buildings").is_array()) why = "not a morphcut-city run report";
      } catch (const std::exception& e) { why = std::string("report is not valid JSON (") + e.what() + ")"; }
    }
    if (!why.empty()) {
      missing.push_back({{"tile", t.name}, {"report", t.report}, {"reason", why}});
      res.missing.push_back(t.name + ": " + why);
      continue;
    }
    ++res.merged;

    const std::string version =
        member(doc, "version").is_string() ? member(doc, "version").get<std::string>() : "";
    const ojson config = result_config(member(doc, "config"));
    std::vector<std::string> mismatch;
    if (ref_tile.empty()) {
      ref_tile = t.name, ref_version = version, ref_config = config;
    } else {
      if (version != ref_version) {
        mismatch.push_back("version");
        res.warnings.push_back("tile " + t.name + ": tool version " + version + " differs from " +
                               ref_version + " (tile " + ref_tile + ")");
      }
      if (config != ref_config) {
        mismatch.push_back("config");
        res.warnings.push_back("tile " + t.name + ": effective config differs from tile " + ref_tile +
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
    if (member(doc, "wall_seconds").is_number()) wall += member(doc, "wall_seconds").get<double>();
    if (cache.is_object()) {
      any_cache = true;
      cache_hits += count_of(member(cache, "hits"));
      cache_misses += count_of(member(cache, "misses"));
    }

    // Building entries, with the tile first.
    const ojson& buildings = doc["buildings"];
    for (const ojson& b : buildings) {
      ojson e = {{"tile", t.name}};
      for (auto it = b.begin(); it != b.end(); ++it) e[it.key()] = it.value();
      const ojson& status = member(b, "status");
      if (status.is_string()) ++res.counts[status.get<std::string>()];
      if (member(b, "id").is_string()) seen[member(b, "id").get<std::string>()].push_back(t.name);
      entries.append(std::string(entry_count++ ? ",\n    " : "\n    ") + e.dump());
    }
    res.buildings += buildings.size();
    if (member(doc, "building_count").is_number() &&
        count_of(member(doc, "building_count")) != buildings.size())
      res.warnings.push_back("tile " + t.name + ": building_count " + member(doc, "building_count").dump() +
                             " but " + std::to_string(buildings.size()) + " entries");

    // CSV rows, with the tile first; rows of a tile with other columns are mapped by name.
    if (csv_file) {
      std::string csv_text;
      if (t.csv.empty() || !read_text(t.csv, csv_text) || tile_columns[i].empty()) {
        res.csv_incomplete = true;
        res.warnings.push_back("tile " + t.name + ": summary CSV " +
                               (t.csv.empty() ? "not given" : t.csv + " missing"));
        s["csv"] = nullptr;
      } else {
        const auto records = csv_records(csv_text);
        const bool same = tile_columns[i] == columns;
        if (!same) res.warnings.push_back("tile " + t.name + ": CSV columns differ from the merged header");
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
            for (size_t c = 0; c < columns.size(); ++c) {
              const auto at = std::find(tile_columns[i].begin(), tile_columns[i].end(), columns[c]);
              const size_t k = static_cast<size_t>(at - tile_columns[i].begin());
              if (c) csv_body << ',';
              if (at != tile_columns[i].end() && k < fields.size()) csv_body << mc::io::csv_escape(fields[k]);
            }
          }
          csv_body << "\r\n";
          ++rows;
        }
        csv_rows.append(csv_body.str());
        res.csv_rows += rows;
        s["csv"] = t.csv;
        s["csv_rows"] = rows;
        if (rows != buildings.size())
          res.warnings.push_back("tile " + t.name + ": " + std::to_string(rows) + " CSV rows but " +
                                 std::to_string(buildings.size()) + " report entries");
      }
    }
    tiles.push_back(std::move(s));
  }

  ojson duplicates = ojson::array();
  for (const auto& [id, where] : seen)
    if (where.size() > 1) duplicates.push_back({{"id", id}, {"tiles", where}});
  res.duplicate_ids = duplicates.size();

  ojson counts = ojson::object();
  for (const auto& [status, n] : res.counts) counts[status] = n;
  ojson head = {
      {"tool", "morphcut-city merge-reports"},
      {"version", MC_VERSION},
      {"tiles", std::move(tiles)},
      {"missing_tiles", std::move(missing)},
      {"totals",
       {{"tiles", res.tiles},
        {"merged", res.merged},
        {"missing", res.tiles - res.merged},
        {"building_count", res.buildings},
        {"counts", counts},
        {"duplicate_ids", res.duplicate_ids},
        {"wall_seconds", wall},
        {"cache", any_cache ? ojson{{"hits", cache_hits}, {"misses", cache_misses}} : ojson(nullptr)},
        {"csv_rows", csv_file ? ojson(res.csv_rows) : ojson(nullptr)}}},
      {"duplicates", std::move(duplicates)},
      {"warnings", res.warnings}};

  std::ostream& o = report_file->stream();
  std::string text = head.dump(2);
  text.pop_back();  // the closing brace: "buildings" follows
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  o << text << ",\n  \"buildings\": [";
  copy_spool(entries, o);
  o << (entry_count ? "\n  ]\n}\n" : "]\n}\n");

  if (csv_file) {
    std::ostream& c = csv_file->stream();
    c << "tile";
    for (const auto& col : columns) c << ',' << mc::io::csv_escape(col);
    c << "\r\n";
    copy_spool(csv_rows, c);
  }
  try {
    report_file->commit();
    if (csv_file) csv_file->commit();
  } catch (const std::exception& e) { throw mc::io::WriteError(std::string("merged outputs: ") + e.what()); }
  return res;
}

}  // namespace mc::report
