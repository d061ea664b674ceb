// Incremental processing: a per-building result cache keyed by content.
//
// key   = SHA-256 of (format tag, MC_VERSION, the result-affecting part of the effective config,
//         the header facts the job reads (CityJSON version, transform, geometry templates), and a
//         canonical serialisation of the building's feature: per object id, type, parents,
//         children and geometry, with every vertex reference replaced by its coordinates on the
//         file's transform grid). Attributes are not in the key: a hit keeps the input's current
//         attributes and only adds what morphcut adds.
// value = DIR/<k0k1>/<key>.json: a header line {"format", "key", "sha256" of the payload line}
//         and the payload: the part objects (vertex indices relative to the new vertices), the
//         new vertices, the morphcut_* attributes and the outcome the report and CSV need.
//
// Only complete results (ok, skipped) are stored: partial and failed ones depend on the
// deadline or may be transient, and are recomputed on every run. Entries are written through
// io/atomic_file (temp + rename), so array tasks sharing one directory never see half an entry;
// an entry whose header, checksum or content does not hold up is ignored with a warning and the
// building is recomputed (and the entry rewritten).
#pragma once
#include <atomic>
#include <cstddef>
#include <string>

#include "config/run_config.hpp"
#include "core/params.hpp"
#include "io/cityjson_common.hpp"
#include "io/cityjson_types.hpp"
#include "report/outcome.hpp"

namespace mc::pipeline {

using mc::report::BuildingOutcome;

struct CacheStats {
  size_t hits = 0, misses = 0;
  size_t stored = 0;      // entries written by this run
  size_t not_stored = 0;  // misses whose outcome is not cacheable (partial, failed)
  size_t corrupt = 0;     // entries ignored (recomputed)
  size_t store_errors = 0;
};

class BuildingCache {
 public:
  // Creates `dir` if needed (throws mc::io::WriteError when it cannot).
  BuildingCache(std::string dir, const mc::io::Header& h, const Params& p, const RunConfig& rc);

  // run_building with the cache in front: a hit rebuilds the outcome from the entry without any
  // geometry work; the feature written is byte-identical to the one run_building returns.
  BuildingOutcome run(mc::io::Feature&& f, const mc::io::Header& h, const Params& p, const RunConfig& rc);

  // The key of a feature whose previous morphcut parts are already stripped.
  std::string key_of(const mc::io::Feature& stripped) const;
  // Where the entry of `key` lives.
  std::string entry_path(const std::string& key) const;

  CacheStats stats() const;
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::string context_;  // everything in the key that is not the building
  mc::io::Transform transform_;
  std::atomic<size_t> hits_{0}, misses_{0}, stored_{0}, not_stored_{0}, corrupt_{0}, store_errors_{0};
};

}  // namespace mc::pipeline
