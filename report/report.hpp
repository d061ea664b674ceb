// The run report (docs/output-format.md): one JSON document with the run's facts first and one
// entry per building after them. Building entries are spooled to an anonymous scratch file as
// they come, so the report costs no memory per building however large the city; the document is
// assembled and committed atomically at the end.
#pragma once
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "report/outcome.hpp"

namespace mc::io {
class AtomicFile;
class ScratchFile;
}  // namespace mc::io

namespace mc::report {

// One building's entry: id, status, reason, lod, timings, sizes, per-level results, Hausdorff.
nlohmann::ordered_json building_report(const BuildingOutcome& b);

class ReportWriter {
 public:
  // Creates the temp file now (fails early on a bad path: throws mc::io::WriteError).
  explicit ReportWriter(const std::string& path);
  ~ReportWriter();
  void add(const BuildingOutcome& b);
  // Writes `run` (an object, keys in the order given) with "buildings": [...] appended, and commits.
  void commit(const nlohmann::ordered_json& run);

 private:
  std::string path_;
  std::unique_ptr<mc::io::AtomicFile> file_;
  std::unique_ptr<mc::io::ScratchFile> spool_;
  size_t entries_ = 0;
};

}  // namespace mc::report
