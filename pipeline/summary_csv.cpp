#include "pipeline/summary_csv.hpp"

#include <cmath>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/errors.hpp"

namespace mc::pipeline {

namespace {
// Shortest round-trip text of a threshold for the column name: 0.1 -> "0.1".
std::string threshold_text(double v) {
  std::ostringstream o;
  o.imbue(std::locale::classic());
  o << v;
  return o.str();
}

void opt(mc::io::CsvWriter& w, const std::optional<double>& v, int precision) {
  if (v && std::isfinite(*v)) w.field(*v, precision);
  else w.empty();
}
void opt(mc::io::CsvWriter& w, double v, int precision) {
  if (std::isfinite(v)) w.field(v, precision);
  else w.empty();
}
}  // namespace

std::vector<std::string> summary_columns(const std::vector<double>& thresholds) {
  std::vector<std::string> c = {"id", "status", "reason", "lod"};
  for (double t : thresholds) c.push_back("parts_" + threshold_text(t));
  for (const char* s : {"height", "footprint_area", "footprint_method", "volume", "convexity",
                        "mean_part_convexity", "largest_part_share", "max_degree", "end_parts", "centroid_x",
                        "centroid_y", "centroid_z", "centroid_method", "lon", "lat"})
    c.push_back(s);
  // The singleton cell's volume check (docs/algorithm.md §6.5): cell / independent estimate, and
  // whether the disagreement exceeds preprocess.volume_check.
  c.push_back("volume_check_ratio");
  c.push_back("volume_check_flagged");
  return c;
}

SummaryWriter::SummaryWriter(const std::string& path, std::vector<double> thresholds)
    : path_(path), thresholds_(std::move(thresholds)) {
  try {
    file_ = std::make_unique<mc::io::AtomicFile>(path);
  } catch (const std::exception& e) {
    throw mc::io::WriteError(path + ": " + e.what());
  }
  csv_ = std::make_unique<mc::io::CsvWriter>(file_->stream());
  for (const auto& c : summary_columns(thresholds_)) csv_->field(c);
  csv_->end_row();
}

SummaryWriter::~SummaryWriter() = default;

void SummaryWriter::add(const BuildingOutcome& b) {
  auto& w = *csv_;
  w.field(b.id).field(b.status).field(b.reason).field(b.lod);
  for (double t : thresholds_) {
    const LevelOutcome* l = nullptr;
    for (const auto& x : b.levels)
      if (x.threshold == t) l = &x;
    if (l) w.field(l->parts);
    else w.empty();
  }
  const Measures& m = b.measures;
  opt(w, m.height, 3);
  opt(w, m.footprint_area, 3);
  w.field(m.footprint_method);
  opt(w, m.volume, 3);
  opt(w, m.convexity, 6);
  if (!b.levels.empty()) {
    const LevelOutcome& f = b.levels.back();
    opt(w, f.mean_convexity, 6);
    opt(w, f.largest_share, 6);
    w.field(f.max_degree).field(f.end_parts);
  } else {
    w.empty().empty().empty().empty();
  }
  if (m.centroid) {
    w.field(m.centroid->x, 3).field(m.centroid->y, 3).field(m.centroid->z, 3);
  } else {
    w.empty().empty().empty();
  }
  w.field(m.centroid_method);
  if (m.lonlat) w.field(m.lonlat->first, 8).field(m.lonlat->second, 8);
  else w.empty().empty();
  opt(w, b.volume_check.ratio, 6);
  if (b.volume_check.method.empty()) w.empty();
  else w.field(b.volume_check.flagged);
  w.end_row();
}

void SummaryWriter::commit() {
  try {
    file_->commit();
  } catch (const std::exception& e) {
    throw mc::io::WriteError(path_ + ": " + e.what());
  }
}

}  // namespace mc::pipeline
