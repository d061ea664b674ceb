// The last repair before a level falls back (docs/output-format.md §Validity): a part that cannot
// be written valid on the output grid is merged into the neighbour it shares the largest face
// with. Such a part holds a feature smaller than the grid (an edge shorter than a step, two faces
// a fold of less than a step apart); inside the union that feature is no longer a boundary, so
// the union often rounds validly where the part did not. The level keeps one part fewer instead
// of falling back to another level.
#pragma once
#include <cstddef>
#include <vector>

#include "core/decompose.hpp"
#include "core/polygon_mesh.hpp"

namespace mc::output {

// The neighbour of part `j` across the largest shared face area (`meshes` are the level's meshes
// from level_part_meshes, whose faces name their neighbour); -1 when it has none.
int largest_neighbour(const std::vector<PolygonMesh>& meshes, size_t j);

// Vertices nearer than two grid steps to a face of their part that they are not on (a storey's
// corner touching the outer wall within a millimetre) are moved away from that face to two steps,
// in every mesh of the level (equal positions move together, so shared faces stay shared). Such a
// vertex crosses the face when rounded (306). Returns the number of vertices moved.
size_t separate_near_touches(std::vector<PolygonMesh>& meshes, double step);

// `parts` with part `j` merged into part `k` (k takes the union of cells, volumes and neighbours;
// its hull and convexity are measured again; j is removed and every index above it shifts down).
std::vector<PartResult> merge_parts(const std::vector<PartResult>& parts, size_t j, size_t k,
                                    const Preprocessed& pre);

}  // namespace mc::output
