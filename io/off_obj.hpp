// OFF and OBJ polygon meshes for single buildings (the paper's samples, debugging output).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/polygon_mesh.hpp"
#include "io/errors.hpp"

namespace mc::io {

using Rgb = std::array<uint8_t, 3>;

// OFF with any of the header variants OFF/COFF/NOFF/CNOFF/STOFF (or none), '#' comments, blank
// lines, counts on the header line or the next, extra per-vertex values (normals, colours) and
// extra per-face values (colours), which are ignored. Throws ReadError (file and line) on bad
// counts, non-numeric or non-finite values, out-of-range indices. Faces with fewer than 3
// vertices are skipped and reported in `problems` when given.
mc::PolygonMesh read_off(const std::string& path, std::vector<std::string>* problems = nullptr);

// OBJ "v" and "f" records (v/vt/vn and negative indices accepted); "usemtl <name>" becomes the
// semantic label of the following faces ("usemtl none" = no label). Other records are ignored.
mc::PolygonMesh read_obj(const std::string& path, std::vector<std::string>* problems = nullptr);

// Atomic writes (temp file + rename). OFF and OBJ have no holes: faces with holes are written as
// one ring joined to each hole by a two-way bridge edge. `face_colours` is empty or one per face.
// Throw WriteError.
void write_off(const std::string& path, const mc::PolygonMesh& mesh,
               const std::vector<Rgb>& face_colours = {});
// Semantic labels are written as "usemtl <label>" groups.
void write_obj(const std::string& path, const mc::PolygonMesh& mesh);

// The face's outer ring with every hole spliced in through a bridge between the closest pair of
// (outer, hole) vertices. A face without holes returns its outer ring.
std::vector<uint32_t> bridge_holes(const mc::PolygonMesh& mesh, const mc::Polygon& face);

}  // namespace mc::io
