// Labelling the carving's cells inside or outside (docs/algorithm.md §6–§8): the oracles (the
// parity vote and the vertical roof-over-ground vote, with the floors of open bottoms), one
// labelling = a carving with one oracle and the singleton repairs, and the volume check that may
// label a second time with the other oracle and keeps the closer cell.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/carve.hpp"
#include "core/carving_planes.hpp"
#include "core/fast_path.hpp"
#include "core/input_frame.hpp"
#include "core/oracle.hpp"
#include "core/preprocess.hpp"
#include "core/surface_index.hpp"

namespace mc {

// One labelling: the complex it carved, its inside cells after the repairs (ascending) and their
// volume, and the repairs' problems.
struct Labelling {
  std::unique_ptr<CellComplex> complex;
  CarveResult carve;
  std::vector<uint32_t> inside;
  std::vector<std::string> problems;
  double volume = 0;
};

class CellLabeller {
 public:
  // Builds the oracles over `oracle_tris` (or the mesh's own triangles when the oracle's weld left
  // none) and waits for the fast path's check (sets out.fast_path, out.fast_path_reason,
  // out.open_bottom_triangles). Keeps references to `in`, `planes`, `p` and `out`.
  CellLabeller(const InputFrame& in, const TriangleSoup& oracle_tris, const CarvingPlanes& planes,
               const PreprocessParams& p, FastPathCheck& fast, Preprocessed& out);
  ~CellLabeller();
  CellLabeller(const CellLabeller&) = delete;
  CellLabeller& operator=(const CellLabeller&) = delete;

  // A carving of a new complex labelled by the vertical vote or by parity, then the singleton
  // repairs: thin cells, cavities, pinch edges (§8).
  Labelling label(bool vertical, Clock::time_point deadline) const;

  const TriangleSoup& oracle_soup() const;
  const TriangleSoup& surface_triangles() const;  // the cleaned mesh's triangles
  const VerticalOracle& vertical() const;

 private:
  struct Oracles;
  const CarvingPlanes& planes_;
  const PreprocessParams& p_;
  const Preprocessed& out_;
  std::unique_ptr<Oracles> o_;
};

// The labelling kept (§6.5): the first oracle's, or the other's when the first disagrees with the
// independent volume estimate (or found no interior) and the other comes closer. Fills
// out.volume_check.
Labelling label_with_volume_check(const CellLabeller& labeller, const CarvingPlanes& planes,
                                  const PreprocessParams& p, Clock::time_point deadline, Preprocessed& out);

}  // namespace mc
