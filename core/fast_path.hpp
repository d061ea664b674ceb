// The fast path's validity check (docs/algorithm.md §6.6): an input that is a valid solid
// (closed, 2-manifold, outward, not self-intersecting; exact predicates) is labelled by one clean
// ray per point instead of the vote. The check reads only the oracle's mesh, so it runs on its
// own task beside the planes and the oracle's build; decide() waits for it.
#pragma once
#include <string>

#include <tbb/task_group.h>

#include "core/params.hpp"
#include "core/polygon_mesh.hpp"
#include "core/preprocess.hpp"
#include "core/solid_validation.hpp"

namespace mc {

class FastPathCheck {
 public:
  // Starts the check of `oracle_mesh` (kept by reference until decide() or destruction) unless the
  // fast path is off, the input is open, or the oracle's weld left no triangle.
  FastPathCheck(const PolygonMesh& oracle_mesh, bool oracle_has_triangles, double diagonal,
                const PreprocessParams& p, bool open_input);
  // Joins the task; when an exception is in flight, its tasks not yet started are cancelled.
  ~FastPathCheck();
  FastPathCheck(const FastPathCheck&) = delete;
  FastPathCheck& operator=(const FastPathCheck&) = delete;

  // Waits for the check and sets out.fast_path and out.fast_path_reason (empty when taken; else
  // "fast path off", "open input", "no valid face at the oracle's weld", the first validity error
  // other than a non-planar face, or "not a closed 2-manifold").
  void decide(Preprocessed& out);

 private:
  std::string reason_;  // why not, known before the check
  bool running_ = false;
  SolidCheck check_;
  tbb::task_group group_;
};

}  // namespace mc
