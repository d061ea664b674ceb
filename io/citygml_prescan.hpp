// The first pass over a CityGML file: libxml2's SAX parser reads it once, building nothing (less
// than half the time of the pull reader's walk), counts the buildings (the pipeline's progress
// estimate) and collects the xlink targets a building names but does not define (surfaces shared
// between buildings), which the main pass could not resolve on its own: it holds one building at
// a time.
#pragma once
#include <string>
#include <unordered_set>

namespace mc::io::citygml {

struct Prescan {
  // Top-level Buildings, as the main pass hands them out; a lower bound when !complete.
  size_t buildings = 0;
  bool complete = false;  // reached the end of the document without an input or XML error
  std::string first_srs;  // the first srsName inside a building (on it or on any geometry)
  // Targets ("id" of xlink:href="#id") of geometry, boundary-surface and part properties that are
  // not gml:ids of the same top-level Building.
  std::unordered_set<std::string> remote_ids;
  size_t remote_id_bytes = 0;
  size_t remote_ids_dropped = 0;  // targets beyond the bounds, not collected

  // Bounds of remote_ids: the memory of this pass must not grow with a hostile file.
  static constexpr size_t kMaxRemoteIds = 1'000'000, kMaxRemoteIdBytes = size_t(64) << 20;
};

// Never throws for the content (the main pass reports errors where it meets them); throws
// ReadError only when the file cannot be opened.
Prescan prescan(const std::string& path);

}  // namespace mc::io::citygml
