// Part meshes -> CityJSON: a closed `Solid` geometry with semantic surfaces, its vertices
// appended to the feature. Vertices are snapped to the output's quantisation grid (the header's
// `transform`) and deduplicated here, not later in the writer, so that what is checked is exactly
// what ends up in the file: every part is checked after quantisation by val3dity's rules at its
// default tolerances, and repaired when it fails them (output/part_repair.hpp,
// docs/output-format.md §Validity).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/polygon_mesh.hpp"
#include "core/solid_validation.hpp"
#include "core/working_frame.hpp"
#include "io/cityjson_common.hpp"
#include "output/solid_check.hpp"

namespace mc::output {

// Appends snapped, deduplicated vertices to a feature's vertex list. Vertices come in the
// building's metric working frame (core/working_frame.hpp); each is mapped to the file's
// coordinates, snapped to the file's grid there, and kept in both forms: the file's for the
// output, the metric image of the snapped point for every check (val3dity's tolerances are
// metres). For a metric file both are the same vector.
class VertexPool {
 public:
  // `step`: the grid's step near the building in metres (the repairs' scale; 0 = unknown).
  VertexPool(std::vector<Vec3>& out, const mc::io::Transform& t, const WorkingFrame& frame = {},
             double step = 0)
      : out_(out), t_(t), frame_(frame), step_(step) {
    if (!frame_.identity())
      for (const Vec3& v : out_) metric_.push_back(frame_.to_metric(v));
  }
  int64_t add(const Vec3& metric);
  // Undo every add() since mark() (a level that turned out invalid leaves no vertices behind).
  size_t mark() const { return out_.size(); }
  void rollback(size_t mark);
  // Vertex clustering: from now on a vertex within `steps` grid steps (Chebyshev) of a vertex
  // added since `mark` is that vertex (0 = exact grid duplicates only). Needs a transform.
  void cluster(int steps, size_t mark) { cluster_ = steps, cluster_from_ = mark; }
  bool can_cluster() const { return t_.present; }
  // The snapped vertices in the metric frame (what the checks read).
  const std::vector<Vec3>& vertices() const { return frame_.identity() ? out_ : metric_; }
  double step() const { return step_; }

 private:
  std::vector<Vec3>& out_;
  std::vector<Vec3> metric_;  // out_ in the working frame, unless the frame is the identity
  mc::io::Transform t_;
  WorkingFrame frame_;
  double step_ = 0;
  std::map<std::tuple<int64_t, int64_t, int64_t>, int64_t> index_;
  int cluster_ = 0;
  size_t cluster_from_ = 0;
};

// A part's boundary on the output grid: faces of rings of VertexPool ids.
struct GridFace {
  std::vector<std::vector<int64_t>> rings;
  int32_t semantic = -1;   // into the part mesh's semantic_labels
  int32_t neighbour = -1;  // the part sharing this face (Polygon::neighbour), or -1
};

struct EncodedSolid {
  nlohmann::json geometry;      // {"type":"Solid","lod":...,"boundaries":...,"semantics":...}
  Shell shell;                  // the boundaries as written
  std::vector<GridFace> faces;  // the same, with each face's neighbour and label
  TriangleShell triangles;      // when valid: its triangles as val3dity builds them (overlap test)
  size_t dropped_faces = 0;     // faces that collapsed to nothing on the grid
  size_t split_faces = 0;       // faces written as several polygons to pass the checks
  bool repaired = false;        // the part needed a repair to pass the checks
  double check_seconds = 0;     // spent checking and repairing
  // Empty when the written solid passes every check; otherwise why not (nothing may be written).
  std::string defect;
};

// A part's faces as rings of pool ids, its vertices added to the pool in face order; a face whose
// outer ring collapses on the grid is left out and counted in `dropped`.
std::vector<GridFace> grid_faces(const PolygonMesh& part, VertexPool& pool, size_t& dropped);

// A part's grid faces checked and repaired (output/part_repair.hpp), and written. It only reads
// the pool's vertices: the parts of a level, their ids taken in order, are checked in parallel.
EncodedSolid checked_solid(std::vector<GridFace> faces, const std::vector<std::string>& semantic_labels,
                           const std::vector<Vec3>& pool, double step, const std::string& lod,
                           const std::string& version);

// grid_faces then checked_solid. `lod` is written as a string, except for CityJSON 1.0 (numeric lods).
EncodedSolid encode_solid(const PolygonMesh& part, const std::string& lod, const std::string& version,
                          VertexPool& pool);

// Sets `solid.geometry` and `solid.shell` from `solid.faces` (after the faces changed).
void write_solid(EncodedSolid& solid, const std::vector<std::string>& semantic_labels, const std::string& lod,
                 const std::string& version);

}  // namespace mc::output
