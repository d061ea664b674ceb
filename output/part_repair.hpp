// Checking and repairing one part after quantisation to the output grid (docs/output-format.md
// §Validity). Rounding every vertex to the grid can bend a face out of its plane, make a ring touch
// itself, or fold a thin sliver; val3dity then rejects the part. The repairs, in order:
//   1. a ring that touches itself at a vertex is split there into simple rings (loops turning like
//      the face become faces of their own, loops turning against it become holes);
//   2. a face that is not planar enough (distance 203, normals 204) or whose ring is still not
//      simple is replaced by its triangles (constrained Delaunay in its plane);
// then the part is checked again. When it still fails, the shell is first closed on the grid (a
// sliver the rounding collapsed leaves a ring that runs along an edge and back, and a T-junction
// beside it: the spike is cut and the vertex put into the edge) and repairs 1 and 2 run again. A part that
// still fails is left to the caller, which clusters the level's vertices more coarsely and encodes it again
// (pipeline/job.cpp).
#pragma once
#include <string>
#include <vector>

#include "core/solid_validation.hpp"
#include "output/part_objects.hpp"

namespace mc::output {

struct PartRepair {
  std::vector<GridFace> faces;  // the faces to write
  size_t split_faces = 0;       // input faces written as several polygons
  bool repaired = false;
  std::string defect;   // empty = passes val3dity's rules at its default tolerances
  TriangleShell shell;  // when valid: the faces' triangles as val3dity builds them (for 601)
};

// `pool` holds the coordinates of the ids in `faces`; `step` is the grid's step in the same units
// (0 when unknown: val3dity's snap distance stands in).
PartRepair check_and_repair(std::vector<GridFace> faces, const std::vector<Vec3>& pool, double step = 0);

// A face shared with another part that is no longer exactly planar on the grid is written as
// triangles, the same ones in both parts (canonical triangulation), so that the two surfaces
// coincide and the parts' interiors stay apart (val3dity's 601 test is exact). Returns the number
// of faces replaced.
size_t triangulate_bent_shared_faces(std::vector<GridFace>& faces, const std::vector<Vec3>& pool);

// After each part of a level was checked and repaired on its own: a repair that changed a face a
// part shares with a neighbour (split it, triangulated it, put a vertex into its edge) leaves the
// two copies different, and val3dity, which triangulates each copy by itself, then finds the two
// parts overlapping (601). For every repaired part, each neighbour whose copy differs gets the
// repaired part's copy (reversed), if it stays valid with it; else the repaired part takes the
// neighbour's copy, if it stays valid. `parts[j]` are part j's faces (GridFace::neighbour indexes
// `parts`). Returns the parts whose faces changed, ascending (docs/output-format.md, Repairs).
std::vector<size_t> align_shared_faces(std::vector<std::vector<GridFace>>& parts,
                                       const std::vector<bool>& repaired, const std::vector<Vec3>& pool);

// The checks alone: val3dity's rules on the faces as they are (first error, or empty).
std::string grid_solid_defect(const std::vector<GridFace>& faces, const std::vector<Vec3>& pool,
                              SolidCheck* check = nullptr);

}  // namespace mc::output
