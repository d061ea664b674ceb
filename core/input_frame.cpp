#include "core/input_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_invoke.h>

#include "core/soup.hpp"
#include "core/thread_tag.hpp"
#include "core/up_axis.hpp"

namespace mc {

InputFrame frame_input(const PolygonMesh& input, const PreprocessParams& p, Preprocessed& out) {
  InputFrame in;
  PolygonMesh mesh = input;
  // "auto" detects the up axis from the faces' orientations (the paper's y-up NYC crops), except
  // for inputs with semantic surfaces (city models: z-up by definition). A model without walls
  // (roofs and ground only: all faces are "walls" about y too) was taken as y-up.
  bool semantic = false;
  for (const Polygon& f : mesh.faces) semantic |= f.semantic >= 0;
  out.up_axis = p.up_axis == "y" ? 1 : (p.up_axis == "z" || semantic ? 2 : detect_up_axis(mesh));
  if (out.up_axis != 2) to_z_up(mesh, out.up_axis);
  BBox raw;
  for (const Polygon& f : mesh.faces)
    for (const auto& r : f.rings)
      for (uint32_t v : r)
        if (v < mesh.vertices.size() && is_finite(mesh.vertices[v])) raw.add(mesh.vertices[v]);
  if (!raw.valid()) throw std::runtime_error("degenerate geometry: no finite vertex");
  in.diagonal = raw.diagonal();
  if (!(in.diagonal > 0)) throw std::runtime_error("degenerate geometry: zero extent");
  // All thresholds are then relative to the building's size.
  out.cell_size = p.cell_size > 0 ? p.cell_size : p.f_d * in.diagonal;
  out.dist = p.dist_thresh > 0 ? p.dist_thresh : out.cell_size / 4;
  out.angle_rad = p.angle_thresh_deg * M_PI / 180.0;
  out.hair = std::max(0.1 * out.dist, p.output_grid);
  // The oracle decides parity per closed shell, and which shells are closed is topology: it
  // sees the input welded only where positions coincide (1e-9 of the diagonal). The weld of
  // the other stages (δ/10, at most 1e-6 of the diagonal) can join float-neighbour vertices of
  // stacked storeys into shells that no longer split into closed patches (sample18 lost two
  // storeys to plain parity).
  // (the two cleanings read the same mesh and are independent: one task each)
  const double diag = in.diagonal;
  tbb::parallel_invoke(with_thread_tag([&] { in.oracle_mesh = clean_soup(mesh, diag * 1e-9, nullptr); }),
                       with_thread_tag([&] {
                         in.mesh = clean_soup(mesh, std::min(out.dist * 0.1, diag * 1e-6), &out.problems);
                       }));
  if (in.mesh.faces.empty()) throw std::runtime_error("degenerate geometry: no valid face after cleaning");
  out.offset = bbox_center(in.mesh);
  translate(in.mesh, -out.offset);
  translate(in.oracle_mesh, -out.offset);
  for (const Vec3& v : in.mesh.vertices) out.box.add(v);
  out.labels = in.mesh.semantic_labels;
  return in;
}

}  // namespace mc
