// A building's input surface as read from a file: a polygon soup with holes and semantic labels.
// This is the hand-over type between io/ (readers) and core/ (preprocessing); it holds no
// file-format details.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace mc {

struct Polygon {
  // rings[0] is the outer boundary, further rings are holes. Indices into PolygonMesh::vertices.
  std::vector<std::vector<uint32_t>> rings;
  // Index into PolygonMesh::semantic_labels, or -1 when the face carries no semantic surface.
  int32_t semantic = -1;
  // For a part of a level (level_part_meshes): the part on the other side of this face, or -1.
  int32_t neighbour = -1;
};

struct PolygonMesh {
  std::vector<Vec3> vertices;
  std::vector<Polygon> faces;
  // Distinct semantic surface type names ("RoofSurface", "WallSurface", "GroundSurface", ...).
  std::vector<std::string> semantic_labels;

  bool empty() const { return faces.empty(); }
  // Index of `label` in semantic_labels, appending it when new.
  int32_t label_index(const std::string& label) {
    for (size_t i = 0; i < semantic_labels.size(); ++i)
      if (semantic_labels[i] == label) return static_cast<int32_t>(i);
    semantic_labels.push_back(label);
    return static_cast<int32_t>(semantic_labels.size() - 1);
  }
  // Whether semantic index `s` (a face's, -1 = none) names `label`.
  bool is_label(int32_t s, const char* label) const {
    return s >= 0 && static_cast<size_t>(s) < semantic_labels.size() && semantic_labels[s] == label;
  }
};

}  // namespace mc
