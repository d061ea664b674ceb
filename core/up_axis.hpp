// Which input axis is vertical. City models are z-up except some (the NYC3D crops, e.g.
// sample11) which are y-up; "vertical", "horizontal" and LoD significance depend on it.
#pragma once
#include "core/polygon_mesh.hpp"
#include "core/vec3.hpp"

namespace mc {

// 1 (y-up) or 2 (z-up). A building is made of walls (normal ⊥ up) and flat roofs and floors
// (normal ∥ up), plus some pitched roofs. For each candidate axis the score is the area fraction
// of faces that are "wall or flat" about it; y is chosen only when it explains the surface
// clearly better than z (z is the default: a box or an axis-aligned house is ambiguous).
int detect_up_axis(const PolygonMesh& mesh);

// Proper rotation (det +1) taking axis `up` (0 x, 1 y, 2 z) to +z, applied to every vertex.
void to_z_up(PolygonMesh& mesh, int up);
Vec3 to_z_up(Vec3 v, int up);
// Inverse of to_z_up.
Vec3 from_z_up(Vec3 v, int up);

// The per-axis scores behind detect_up_axis (for diagnostics and tests).
struct UpAxisScores {
  double axis[3] = {0, 0, 0};  // area fraction of faces with normal ⊥ or ∥ that axis (±10°)
};
UpAxisScores up_axis_scores(const PolygonMesh& mesh);

}  // namespace mc
