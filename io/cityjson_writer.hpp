// Streaming CityJSON writer: .city.json or CityJSONSeq (.city.jsonl, by extension), atomic.
#pragma once
#include <memory>
#include <string>

#include "io/cityjson_types.hpp"
#include "io/errors.hpp"

namespace mc::io {

class CityJsonWriter {
 public:
  // Writes the header at once (same version and root members as `header`). Throws WriteError.
  CityJsonWriter(const std::string& path, const Header& header);
  // Without close(), the temp file is removed: no half-written output ever appears at `path`.
  ~CityJsonWriter();
  CityJsonWriter(const CityJsonWriter&) = delete;
  CityJsonWriter& operator=(const CityJsonWriter&) = delete;

  // Streams the feature's objects; vertices are re-quantised with the header's transform
  // (CityJSON needs integer vertices when there is one; 1.0 files without one get floats).
  // A .city.json output cannot hold a feature's own members (`extra`, e.g. a CityJSONSeq
  // feature's local "appearance"): those are counted in dropped_extras(); .city.jsonl keeps them.
  void write(const Feature& f);
  // Finalises the file and renames it into place. Throws WriteError.
  void close();

  size_t features_written() const;
  size_t dropped_extras() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc::io
