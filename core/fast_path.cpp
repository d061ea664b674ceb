#include "core/fast_path.hpp"

#include <exception>

#include "core/thread_tag.hpp"

namespace mc {

FastPathCheck::FastPathCheck(const PolygonMesh& oracle_mesh, bool oracle_has_triangles, double diagonal,
                             const PreprocessParams& p, bool open_input) {
  if (!p.fast_path) reason_ = "fast path off";
  else if (open_input) reason_ = "open input";
  else if (!oracle_has_triangles) reason_ = "no valid face at the oracle's weld";
  if (!reason_.empty()) return;
  running_ = true;
  group_.run(with_thread_tag([this, &oracle_mesh, diagonal] {
    SolidTolerances tol;
    tol.snap = diagonal * 1e-9;  // the oracle's weld: its topology is the one checked
    check_ = check_solid(oracle_mesh, tol, false);
  }));
}

FastPathCheck::~FastPathCheck() {
  if (!running_) return;
  if (std::uncaught_exceptions() > 0) group_.cancel();
  try {
    group_.wait();
  } catch (...) {}  // the exception in flight is the error
}

void FastPathCheck::decide(Preprocessed& out) {
  if (!running_) {
    out.fast_path_reason = reason_;
    return;
  }
  group_.wait();
  running_ = false;
  // (non-planar faces, 203/204, do not matter to the rays)
  out.fast_path = check_.closed_manifold;
  out.fast_path_reason = "not a closed 2-manifold";
  for (const SolidError& e : check_.errors)
    if (e.code != solid_code::kNonPlanarPolygon && e.code != solid_code::kNonPlanarNormals) {
      out.fast_path_reason = std::to_string(e.code) + " " + e.name;
      break;
    }
  if (out.fast_path) out.fast_path_reason.clear();
}

}  // namespace mc
