// Part meshes -> CityJSON: a closed `Solid` geometry with semantic surfaces, its vertices
// appended to the feature. Vertices are snapped to the output's quantisation grid (the header's
// `transform`) and deduplicated here, not later in the writer, so that what is checked for
// closedness is exactly what ends up in the file.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/polygon_mesh.hpp"
#include "io/cityjson_common.hpp"
#include "pipeline/solid_check.hpp"

namespace mc::pipeline {

// Appends snapped, deduplicated vertices to a feature's vertex list.
class VertexPool {
 public:
  VertexPool(std::vector<Vec3>& out, const mc::io::Transform& t) : out_(out), t_(t) {}
  int64_t add(const Vec3& v);
  // Undo every add() since mark() (a level that turned out invalid leaves no vertices behind).
  size_t mark() const { return out_.size(); }
  void rollback(size_t mark);

 private:
  std::vector<Vec3>& out_;
  mc::io::Transform t_;
  std::map<std::tuple<int64_t, int64_t, int64_t>, int64_t> index_;
};

struct EncodedSolid {
  nlohmann::json geometry;  // {"type":"Solid","lod":...,"boundaries":...,"semantics":...}
  Shell shell;              // the boundaries as written (for the closedness check)
  size_t dropped_faces = 0; // faces that collapsed to nothing on the grid
};

// `lod` is written as a string, except for CityJSON 1.0 (numeric lods).
EncodedSolid encode_solid(const PolygonMesh& part, const std::string& lod, const std::string& version,
                          VertexPool& pool);

}  // namespace mc::pipeline
