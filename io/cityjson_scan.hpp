// Pass 1 over a .city.json with nlohmann's SAX interface: keeps the root members (small), spills
// the vertex list to a scratch file, and indexes every CityObject by byte range and parent links.
// Nothing of the CityObjects' content is kept, so memory does not grow with the file's geometry.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/scratch_file.hpp"

namespace mc::io {

struct ObjectEntry {
  uint64_t begin = 0, end = 0;          // byte range of the object's JSON value in the file
  uint32_t id_offset = 0, id_size = 0;  // the id, in DocumentIndex::ids
};

struct DocumentIndex {
  nlohmann::json root = nlohmann::json::object();  // every root member but CityObjects, vertices
  bool has_city_objects = false, has_vertices = false;
  std::string ids;                   // all object ids, back to back
  std::vector<ObjectEntry> objects;  // in file order
  // Parent links as written, resolved to indices after the scan: (object, parent id) from
  // "parents" and (parent object, child id) from "children".
  std::vector<std::pair<uint32_t, std::string>> parent_refs, child_refs;
  uint64_t vertex_count = 0;          // raw (untransformed) xyz doubles in the spill file
  std::vector<std::string> problems;  // not attributable to one feature

  std::string_view id(const ObjectEntry& e) const { return {ids.data() + e.id_offset, e.id_size}; }
};

// Runs pass 1 over the open file `fd`. Throws ReadError (naming `source`) on malformed JSON or a
// root that is not a JSON object; vertex problems go into problems.
DocumentIndex scan_document(int fd, const std::string& source, ScratchFile& vertex_spill);

}  // namespace mc::io
