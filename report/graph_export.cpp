#include "report/graph_export.hpp"

#include <cstdlib>
#include <set>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/gpkg_writer.hpp"
#include "output/rounding.hpp"
#include "report/summary_csv.hpp"

namespace mc::report {

using namespace mc::massing;
using namespace mc::output;

GraphWriter::GraphWriter(const std::string& path) : path_(path) {
  try {
    file_ = std::make_unique<mc::io::AtomicFile>(path);
  } catch (const std::exception& e) { throw mc::io::WriteError(path + ": " + e.what()); }
}

GraphWriter::~GraphWriter() = default;

void GraphWriter::add(const BuildingOutcome& b) {
  file_->stream() << graph_json(b.id, b.status, b.massing).dump() << '\n';
}

void GraphWriter::commit() {
  try {
    file_->commit();
  } catch (const std::exception& e) { throw mc::io::WriteError(path_ + ": " + e.what()); }
}

namespace {
// Column types by name (an example row would depend on the first building): integers and reals
// as the CSV writes them, text for every other column (a column added to the CSV later is text
// until it is named here).
std::vector<mc::io::GpkgColumn> gpkg_columns(const std::vector<double>& thresholds) {
  static const std::set<std::string> reals = {"height",
                                              "footprint_area",
                                              "volume",
                                              "convexity",
                                              "mean_part_convexity",
                                              "largest_part_share",
                                              "centroid_x",
                                              "centroid_y",
                                              "centroid_z",
                                              "lon",
                                              "lat",
                                              "morphcut_massing_level",
                                              "volume_check_ratio"};
  static const std::set<std::string> texts = {"morphcut_tower_on_podium"};
  std::vector<mc::io::GpkgColumn> cols;
  for (const auto& name : summary_columns(thresholds)) {
    mc::io::GpkgType t = mc::io::GpkgType::Text;
    if (reals.count(name)) t = mc::io::GpkgType::Real;
    else if (!texts.count(name) && (name.rfind("parts_", 0) == 0 || name == "max_degree" ||
                                    name == "end_parts" || name.rfind("morphcut_", 0) == 0))
      t = mc::io::GpkgType::Integer;
    cols.push_back({name, t});
  }
  return cols;
}
}  // namespace

MassingGpkgWriter::MassingGpkgWriter(const std::string& path, const std::string& crs,
                                     std::vector<double> thresholds, int coordinate_decimals)
    : thresholds_(std::move(thresholds)),
      decimals_(coordinate_decimals),
      columns_(gpkg_columns(thresholds_)),
      gpkg_(std::make_unique<mc::io::GpkgWriter>(path, crs, columns_)) {}

MassingGpkgWriter::~MassingGpkgWriter() = default;

void MassingGpkgWriter::add(const BuildingOutcome& b) {
  std::vector<mc::io::GpkgValue> values;
  const std::vector<SummaryCell> row = summary_row(b, thresholds_, decimals_);
  for (size_t i = 0; i < row.size() && i < columns_.size(); ++i) {
    const SummaryCell& c = row[i];
    mc::io::GpkgValue v;
    if (c.kind != SummaryCell::Empty) {
      char* end = nullptr;
      const double x = std::strtod(c.text.c_str(), &end);  // the CSV's rounding
      const bool number = end && *end == '\0' && !c.text.empty();
      if (columns_[i].type == mc::io::GpkgType::Text) v.text = c.text;
      else if (columns_[i].type == mc::io::GpkgType::Integer && c.kind == SummaryCell::Integer)
        v.integer = c.integer;
      else if (number) v.real = x;
      else v.text = c.text;
    }
    values.push_back(std::move(v));
  }
  gpkg_->add_building(b.massing.footprint, values);
  for (const LevelMassing& L : b.massing.levels)
    for (size_t j = 0; j < L.parts.size(); ++j) {
      const PartMassing& pm = L.parts[j];
      mc::io::GpkgPart p;
      p.building = b.id;
      p.id = b.id + "-mc" + std::to_string(L.index) + "-" + std::to_string(j);
      p.role = pm.role;
      p.mass = pm.mass;
      p.piece = pm.piece;
      p.level = L.threshold;
      p.index = static_cast<int>(j);
      p.z_min = rounded(pm.z_min, 1e-6);
      p.z_max = rounded(pm.z_max, 1e-6);
      p.volume = rounded(pm.volume, 1e-6);
      p.convexity = rounded(pm.convexity, 1e-9);
      p.footprint_area = rounded(pm.footprint_area, 1e-6);
      p.grounded = pm.grounded;
      p.footprint = pm.footprint;
      gpkg_->add_part(p);
    }
}

void MassingGpkgWriter::commit() { gpkg_->commit(); }

std::string graph_path_for_stem(const std::string& stem) { return stem + ".morphcut.graph.jsonl"; }
std::string gpkg_path_for_stem(const std::string& stem) { return stem + ".morphcut.gpkg"; }

}  // namespace mc::report
