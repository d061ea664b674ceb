#include "report/summary_csv.hpp"

#include <cmath>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/errors.hpp"

namespace mc::report {

using namespace mc::massing;

namespace {
// Shortest round-trip text of a threshold for the column name: 0.1 -> "0.1".
std::string threshold_text(double v) {
  std::ostringstream o;
  o.imbue(std::locale::classic());
  o << v;
  return o.str();
}

using Row = std::vector<SummaryCell>;
void text(Row& r, const std::string& s) { r.push_back({SummaryCell::Text, s, 0, 0, 0}); }
void integer(Row& r, long long v) { r.push_back({SummaryCell::Integer, std::to_string(v), v, 0, 0}); }
void empty(Row& r) { r.push_back({}); }
void real(Row& r, double v, int precision) {
  if (!std::isfinite(v)) return empty(r);
  r.push_back({SummaryCell::Real, mc::io::format_fixed(v, precision), 0, v, precision});
}
void opt(Row& r, const std::optional<double>& v, int precision) {
  if (v) real(r, *v, precision);
  else empty(r);
}
}  // namespace

std::vector<std::string> summary_columns(const std::vector<double>& thresholds) {
  std::vector<std::string> c = {"id", "status", "reason", "lod"};
  for (double t : thresholds) c.push_back("parts_" + threshold_text(t));
  for (const char* s : {"height", "footprint_area", "footprint_method", "volume", "convexity",
                        "mean_part_convexity", "largest_part_share", "max_degree", "end_parts", "centroid_x",
                        "centroid_y", "centroid_z", "centroid_method", "lon", "lat"})
    c.push_back(s);
  for (const auto& s : massing_columns()) c.push_back(s);  // massing/massing.hpp
  // The singleton cell's volume check (docs/algorithm.md §6.5): cell / independent estimate, and
  // whether the disagreement exceeds preprocess.volume_check.
  c.push_back("volume_check_ratio");
  c.push_back("volume_check_flagged");
  return c;
}

std::vector<SummaryCell> summary_row(const BuildingOutcome& b, const std::vector<double>& thresholds,
                                     int coordinate_decimals) {
  Row w;
  text(w, b.id);
  text(w, b.status);
  text(w, b.reason);
  text(w, b.lod);
  for (double t : thresholds) {
    const LevelOutcome* l = nullptr;
    for (const auto& x : b.levels)
      if (x.threshold == t) l = &x;
    if (l) integer(w, static_cast<long long>(l->parts));
    else empty(w);
  }
  const Measures& m = b.measures;
  opt(w, m.height, 3);
  opt(w, m.footprint_area, 3);
  text(w, m.footprint_method);
  opt(w, m.volume, 3);
  opt(w, m.convexity, 6);
  if (!b.levels.empty()) {
    const LevelOutcome& f = b.levels.back();
    real(w, f.mean_convexity, 6);
    real(w, f.largest_share, 6);
    integer(w, f.max_degree);
    integer(w, f.end_parts);
  } else {
    for (int i = 0; i < 4; ++i) empty(w);
  }
  if (m.centroid) {
    real(w, m.centroid->x, coordinate_decimals);
    real(w, m.centroid->y, coordinate_decimals);
    real(w, m.centroid->z, 3);
  } else {
    for (int i = 0; i < 3; ++i) empty(w);
  }
  text(w, m.centroid_method);
  if (m.lonlat) {
    real(w, m.lonlat->first, 8);
    real(w, m.lonlat->second, 8);
  } else {
    empty(w);
    empty(w);
  }
  const MassingFeatures& f = b.massing.features;
  if (f.valid) {
    real(w, f.level, 6);
    for (int v : {f.tiers, f.setbacks, f.wings, f.annexes, f.rooftop_units, f.courtyards}) integer(w, v);
    text(w, f.tower_on_podium ? "true" : "false");
    integer(w, f.edges);
    integer(w, f.cycles);
  } else {
    for (size_t i = 0; i < massing_columns().size(); ++i) empty(w);
  }
  real(w, b.volume_check.ratio, 6);
  if (b.volume_check.method.empty()) empty(w);
  else text(w, b.volume_check.flagged ? "true" : "false");
  return w;
}

SummaryWriter::SummaryWriter(const std::string& path, std::vector<double> thresholds, int coordinate_decimals)
    : path_(path), thresholds_(std::move(thresholds)), decimals_(coordinate_decimals) {
  try {
    file_ = std::make_unique<mc::io::AtomicFile>(path);
  } catch (const std::exception& e) { throw mc::io::WriteError(path + ": " + e.what()); }
  csv_ = std::make_unique<mc::io::CsvWriter>(file_->stream());
  for (const auto& c : summary_columns(thresholds_)) csv_->field(c);
  csv_->end_row();
}

SummaryWriter::~SummaryWriter() = default;

void SummaryWriter::add(const BuildingOutcome& b) {
  auto& w = *csv_;
  for (const SummaryCell& c : summary_row(b, thresholds_, decimals_)) {
    if (c.kind == SummaryCell::Empty) w.empty();
    else if (c.kind == SummaryCell::Text) w.field(c.text);
    else if (c.kind == SummaryCell::Integer) w.field(c.integer);
    else w.field(c.real, c.precision);
  }
  w.end_row();
}

void SummaryWriter::commit() {
  try {
    file_->commit();
  } catch (const std::exception& e) { throw mc::io::WriteError(path_ + ": " + e.what()); }
}

}  // namespace mc::report
