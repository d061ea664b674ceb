// Streaming CityJSON reader: .city.json (1.0, 1.1, 2.0) and CityJSONSeq (.city.jsonl), one
// Feature (a top-level CityObject with its descendants) at a time.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/cityjson_types.hpp"
#include "io/errors.hpp"

namespace mc::io {

class CityJsonReader {
 public:
  // Format by extension: ".jsonl" (or "-" = stdin) is CityJSONSeq, anything else a .city.json.
  // A .city.json is read in two streaming passes (see cityjson_reader_doc.cpp), never as one DOM.
  // Throws ReadError for file-level failures (cannot open, malformed JSON, not CityJSON,
  // unsupported version, missing CityObjects/vertices).
  explicit CityJsonReader(const std::string& path);
  ~CityJsonReader();
  CityJsonReader(CityJsonReader&&) noexcept;
  CityJsonReader& operator=(CityJsonReader&&) noexcept;

  const Header& header() const;
  // The next feature in file order; false at the end. Per-object problems go into out.problems.
  bool next(Feature& out);
  // Problems not attributable to one feature: malformed vertex entries, CityObjects that are not
  // JSON objects, unreadable CityJSONSeq lines (skipped, the rest of the file is still read).
  const std::vector<std::string>& problems() const;
  bool is_sequence() const;
  // Features in the file, known after the document's first pass (nullopt for CityJSONSeq).
  std::optional<size_t> feature_count() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc::io
