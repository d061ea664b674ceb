#include "core/preprocess.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/carve.hpp"
#include "core/carving_planes.hpp"
#include "core/cell_labelling.hpp"
#include "core/fast_path.hpp"
#include "core/hausdorff.hpp"
#include "core/input_frame.hpp"
#include "core/open_input.hpp"
#include "core/soup.hpp"
#include "core/surface.hpp"
#include "core/up_axis.hpp"

namespace mc {

Vec3 Preprocessed::to_input(const Vec3& p) const { return from_z_up(p + offset, up_axis); }

namespace {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

struct FidelityInputs {
  TriangleSoup input, cell;  // the input's triangles and the cell's boundary, centred frame
  double step = 0;           // sampling step
  bool means = true;         // the mean distances too (PreprocessParams::mean_distances)
};

void measure_fidelity(Preprocessed& pre) {
  if (!pre.pending_fidelity) return;
  const FidelityInputs& f = *pre.pending_fidelity;
  const HausdorffResult h = hausdorff(f.input, f.cell, f.step, f.means);
  pre.hausdorff = h.symmetric;
  pre.hausdorff_in_to_cell = h.a_to_b;
  pre.hausdorff_cell_to_in = h.b_to_a;
  pre.mean_distance = h.mean_a_to_b;
  pre.mean_distance_cell_to_in = h.mean_b_to_a;
  pre.mean_distance_symmetric = h.mean_symmetric;
  pre.pending_fidelity.reset();
}

namespace {

// The chosen labelling's complex and inside cells become the singleton cell's (§6.5, §8).
std::vector<uint32_t> adopt(Labelling chosen, const PreprocessParams& p, Preprocessed& out) {
  out.complex = std::move(chosen.complex);
  const CarveResult& cr = chosen.carve;
  out.cells = cr.cells;
  out.inside_cells = cr.inside.size();
  out.oracle_points = cr.points;
  out.truncated = cr.truncated;
  if (cr.inside.empty()) throw std::runtime_error("no interior: the oracle found no inside cell");
  out.problems.insert(out.problems.end(), chosen.problems.begin(), chosen.problems.end());
  if (chosen.inside.empty()) throw std::runtime_error("no interior left after removing pinch edges");
  VolumeCheck& vc = out.volume_check;
  vc.cell = chosen.volume;
  vc.ratio = vc.estimate > 0 ? vc.cell / vc.estimate : 1.0;
  vc.flagged = p.volume_check > 0 && vc.estimate > 0 && std::abs(vc.cell / vc.estimate - 1) > p.volume_check;
  if (vc.flagged)
    out.problems.push_back("volume check: cell " + std::to_string(vc.cell) + " vs " + vc.method +
                           " estimate " + std::to_string(vc.estimate) + " (ratio " +
                           std::to_string(vc.ratio) + ", oracle " + vc.oracle +
                           (vc.relabelled ? ", after a second labelling" : "") + ")");
  return std::move(chosen.inside);
}

// Face-connected components of the inside cells, largest first; each is its own singleton cell,
// none is dropped unless below min_component_fraction (§8).
void split_components(const std::vector<uint32_t>& inside, const PreprocessParams& p, Preprocessed& out) {
  auto comps = connected_components(*out.complex, inside);
  double total = 0;
  std::vector<SingletonComponent> sc;
  for (auto& c : comps) {
    const double v = surface_volume(*out.complex, c);
    total += v;
    sc.push_back({std::move(c), v});
  }
  std::stable_sort(sc.begin(), sc.end(), [](const auto& a, const auto& b) { return a.volume > b.volume; });
  for (auto& c : sc) {
    if (c.volume < p.min_component_fraction * total) {
      ++out.dropped_components;
      out.dropped_volume += c.volume;
    } else {
      out.components.push_back(std::move(c));
    }
  }
  if (out.dropped_components)
    out.problems.push_back("dropped " + std::to_string(out.dropped_components) +
                           " small interior component(s), volume " + std::to_string(out.dropped_volume));
}

// Closedness of the whole singleton (all components), and what the fidelity measure needs.
void check_singleton(const TriangleSoup& input_triangles, const PreprocessParams& p, Preprocessed& out) {
  std::vector<uint32_t> all;
  for (const auto& c : out.components) all.insert(all.end(), c.cells.begin(), c.cells.end());
  const Surface s = extract_surface(*out.complex, all);
  out.closed = s.closed();
  out.manifold = s.nonmanifold_edges == 0;
  if (!p.compute_hausdorff) return;
  auto f = std::make_shared<FidelityInputs>();
  boundary_triangles(*out.complex, all, Vec3{}, f->cell.vertices, f->cell.triangles);
  f->step = std::max(out.box.diagonal() * p.hausdorff_error * 10, out.cell_size / 2);
  f->input = input_triangles;
  f->means = p.mean_distances;
  out.pending_fidelity = std::move(f);
}

}  // namespace

// The paper's pipeline (docs/algorithm.md §1): frame and clean, planes, oracles, label (with the
// volume check), components, fidelity.
Preprocessed preprocess(const PolygonMesh& input, const PreprocessParams& p, Clock::time_point deadline,
                        double terrain_z, bool defer_fidelity) {
  const auto t0 = Clock::now();
  Preprocessed out;
  out.input_faces = input.faces.size();
  if (input.faces.empty()) throw std::runtime_error("empty geometry: no faces");
  InputFrame in = frame_input(input, p, out);  // §2
  // Open inputs (missing walls, grounds, roofs, §6.4) are known before the planes: the vertical
  // planes of their open boundary come after the hole planes, so that a missing wall is closed
  // where its roof or ground ends.
  const OpenInput open = analyse_open_input(in.mesh, out.dist);
  out.open_input = open.open(out.cell_size);
  const TriangleSoup oracle_tris = triangulate(in.oracle_mesh);
  FastPathCheck fast(in.oracle_mesh, !oracle_tris.triangles.empty(), in.diagonal, p, out.open_input);  // §6.6
  const CarvingPlanes planes = carving_planes(in, open, p, terrain_z, out);  // §3–§5
  const CellLabeller labeller(in, oracle_tris, planes, p, fast, out);        // §6
  const std::vector<uint32_t> inside =
      adopt(label_with_volume_check(labeller, planes, p, deadline, out), p, out);
  split_components(inside, p, out);  // §8
  check_singleton(labeller.surface_triangles(), p, out);
  if (!defer_fidelity) measure_fidelity(out);
  out.seconds = seconds_since(t0);
  return out;
}

}  // namespace mc
