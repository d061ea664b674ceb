#include "pipeline/level_encoding.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <mutex>

#include <tbb/parallel_for.h>

#include "core/hull.hpp"
#include "core/thread_tag.hpp"
#include "io/off_obj.hpp"
#include "output/part_merge.hpp"
#include "output/part_repair.hpp"
#include "output/rounding.hpp"

namespace mc::pipeline {

using namespace mc::output;
using namespace mc::report;
using nlohmann::json;

std::string part_id(const std::string& building, size_t level, size_t index) {
  return building + "-mc" + std::to_string(level) + "-" + std::to_string(index);
}

namespace {

// The first pair of parts whose interiors overlap on the grid, as val3dity tests them (601, exact),
// with the smaller part of the pair; {"", -1} when none (docs/output-format.md, "Checked, not
// assumed"). Rounding can push a vertex of a part a fraction of a step into its neighbour, and the
// non-conforming encoding lets a neighbour's corner stand inside a part; the smaller part then
// fails the level, so the repairs after it (clustering, then merging it into its neighbour) run as
// for any defect.
std::pair<std::string, int> first_overlap(const std::vector<EncodedSolid>& solids,
                                          const std::vector<PartResult>& parts, const VertexPool& pool,
                                          bool conforming, bool plain) {
  const std::vector<Vec3>& grid = pool.vertices();
  // Two parts of the conforming encoding share their common faces vertex for vertex (written as the
  // same triangles when bent, output/part_repair.hpp), so their interiors are apart when the plane
  // of a shared face has every other vertex of one part on one side and of the other on the other
  // side; the shared faces' own vertices, a fraction of a step off that plane after rounding, are
  // on both parts' surfaces and left out.
  auto shared_face_separates = [&](size_t j, size_t k) {
    if (!conforming) return false;
    std::vector<int64_t> shared;
    const GridFace* face = nullptr;
    for (const GridFace& f : solids[j].faces)
      if (f.neighbour == static_cast<int>(k) && !f.rings.empty()) {
        for (const auto& ring : f.rings) shared.insert(shared.end(), ring.begin(), ring.end());
        if (!face || f.rings[0].size() > face->rings[0].size()) face = &f;
      }
    if (!face || face->rings[0].size() < 3) return false;
    std::sort(shared.begin(), shared.end());
    auto others = [&](size_t part) {
      std::vector<Vec3> pts;
      for (const GridFace& f : solids[part].faces)
        for (const auto& ring : f.rings)
          for (int64_t id : ring)
            if (!std::binary_search(shared.begin(), shared.end(), id))
              pts.push_back(grid[static_cast<size_t>(id)]);
      return pts;
    };
    const auto& ring = face->rings[0];
    const size_t n = ring.size();
    return plane_separates(grid[static_cast<size_t>(ring[0])], grid[static_cast<size_t>(ring[n / 3])],
                           grid[static_cast<size_t>(ring[(2 * n) / 3])], others(j), others(k));
  };
  std::vector<BBox> boxes(solids.size());
  for (size_t j = 0; j < solids.size(); ++j)
    for (const Vec3& v : solids[j].triangles.points) boxes[j].add(v);
  std::vector<std::vector<std::array<Vec3, 3>>> hulls(solids.size());  // built once, when needed
  std::vector<std::once_flag> hull_built(solids.size());
  auto hull_of = [&](size_t j) -> const std::vector<std::array<Vec3, 3>>& {
    std::call_once(hull_built[j], [&] { hulls[j] = hull_facets(solids[j].triangles.points); });
    return hulls[j];
  };
  // On the first, plain encoding every vertex is its exact position rounded (at most half a step
  // away) and the parts were apart before: two parts can only overlap where a vertex of one, not on
  // the other, comes within a step of the other's surface. Repaired parts are tested in full.
  const double near = 2 * std::max(pool.step(), val3dity_tolerances().snap);
  auto apart = [&](size_t j, size_t k) {
    if (!plain || solids[j].repaired || solids[k].repaired) return false;
    return min_distance_beyond(solids[j].triangles, solids[k].triangles, near) &&
           min_distance_beyond(solids[k].triangles, solids[j].triangles, near);
  };
  auto overlap = [&](size_t j, size_t k) {
    for (int axis = 0; axis < 3; ++axis)
      if (boxes[j].hi[axis] <= boxes[k].lo[axis] || boxes[k].hi[axis] <= boxes[j].lo[axis]) return false;
    if (shared_face_separates(j, k) || apart(j, k)) return false;
    if (facet_separates(hull_of(j), solids[k].triangles.points) ||
        facet_separates(hull_of(k), solids[j].triangles.points))
      return false;
    return interiors_overlap_exact(solids[j].triangles, solids[k].triangles);
  };
  // Each part's first overlapping later part, the parts in parallel; the first pair in (j, k)
  // order is the one reported, as in a scan one pair at a time.
  std::vector<size_t> first(solids.size(), 0);
  tbb::parallel_for(size_t(0), solids.size(), with_thread_tag([&](size_t j) {
                      for (size_t k = j + 1; k < solids.size(); ++k)
                        if (overlap(j, k)) {
                          first[j] = k;
                          break;
                        }
                    }));
  for (size_t j = 0; j < solids.size(); ++j)
    if (const size_t k = first[j]; k > 0)
      return {"parts " + std::to_string(j) + " and " + std::to_string(k) +
                  " overlap on the output grid (601 BUILDINGPARTS_OVERLAP)",
              static_cast<int>(parts[k].volume < parts[j].volume ? k : j)};
  return {"", -1};
}

// A part repaired on its own may have changed a face it shares: both copies made the same again
// (repairs are rare: nothing to do, and nothing copied, without one).
void align_repaired_parts(std::vector<EncodedSolid>& solids, const std::vector<PolygonMesh>& meshes,
                          const VertexPool& pool, const std::string& lod, const std::string& version) {
  if (std::none_of(solids.begin(), solids.end(), [](const EncodedSolid& s) { return s.repaired; })) return;
  std::vector<std::vector<GridFace>> faces;
  std::vector<bool> repaired;
  for (EncodedSolid& solid : solids) {
    faces.push_back(std::move(solid.faces));
    repaired.push_back(solid.repaired);
  }
  const std::vector<size_t> changed = align_shared_faces(faces, repaired, pool.vertices());
  for (size_t k = 0; k < solids.size(); ++k) solids[k].faces = std::move(faces[k]);
  for (size_t k : changed) {
    write_solid(solids[k], meshes[k].semantic_labels, lod, version);
    solids[k].repaired = true;  // counted with the repaired parts
    SolidCheck check;
    grid_solid_defect(solids[k].faces, pool.vertices(), &check);
    solids[k].triangles = std::move(check.shell);
  }
}

// The level's valid parts as staged BuildingParts, with the level's convexity and degree figures.
void stage_parts(const std::string& building, size_t i, double threshold,
                 const std::vector<PartResult>& parts, std::vector<PolygonMesh>& meshes,
                 std::vector<EncodedSolid>& solids, EncodedLevel& e) {
  double total_volume = 0, largest = 0, weighted_cvx = 0, sum_cvx = 0, min_cvx = 1;
  for (size_t j = 0; j < parts.size(); ++j) {
    const PartResult& part = parts[j];
    PolygonMesh& mesh = meshes[j];
    double hull_volume = part.hull_volume;
    if (!(hull_volume > 0)) hull_volume = convex_hull(mesh.vertices).volume;  // singleton parts
    const double convexity = hull_volume > 0 ? std::min(1.0, part.volume / hull_volume) : 0.0;
    EncodedSolid& solid = solids[j];
    e.dropped_faces += solid.dropped_faces;
    e.repaired_parts += solid.repaired;
    e.split_faces += solid.split_faces;
    json neighbours = json::array();
    for (uint32_t n : part.neighbours) neighbours.push_back(part_id(building, i, n));
    const int degree = static_cast<int>(part.neighbours.size());
    e.lv.max_degree = std::max(e.lv.max_degree, degree);
    e.lv.end_parts += degree == 1;
    total_volume += part.volume;
    largest = std::max(largest, part.volume);
    weighted_cvx += convexity * part.volume;
    sum_cvx += convexity;
    min_cvx = std::min(min_cvx, convexity);
    json obj = {{"type", "BuildingPart"},
                {"parents", json::array({building})},
                {"attributes",
                 {{"morphcut_level", threshold},
                  {"morphcut_index", j},
                  {"volume", rounded(part.volume, 1e-6)},
                  {"convexity", rounded(convexity, 1e-9)},
                  {"neighbours", neighbours}}},
                {"geometry", json::array({std::move(solid.geometry)})}};
    e.staged.push_back({part_id(building, i, j), std::move(obj)});
    e.meshes.push_back(std::move(mesh));
  }
  if (total_volume > 0) e.lv.largest_share = largest / total_volume;
  e.lv.convexity = total_volume > 0 ? weighted_cvx / total_volume : 0.0;
  e.lv.mean_convexity = sum_cvx / static_cast<double>(parts.size());
  e.lv.min_convexity = min_cvx;
}

EncodedLevel encode_level(const std::string& building, size_t i, double threshold,
                          const std::vector<PartResult>& parts, const Preprocessed& pre,
                          const std::string& lod, const std::string& version, VertexPool& pool,
                          bool conforming, bool separate = false, bool plain = false,
                          const std::vector<PolygonMesh>* level_meshes = nullptr) {
  EncodedLevel e;
  e.lv.index = i;
  e.lv.threshold = threshold;
  e.lv.parts = parts.size();
  if (parts.empty()) {
    e.defect = "no parts";
    return e;
  }
  std::vector<PolygonMesh> meshes;
  if (conforming) meshes = level_meshes ? *level_meshes : level_part_meshes(pre, parts);
  else
    for (const auto& part : parts) meshes.push_back(part_mesh(pre, part));
  if (separate) separate_near_touches(meshes, pool.step());
  // Vertex ids in part order (the pool's numbering), then every part checked on its own in
  // parallel: the first invalid part fails the level, as when checked one by one (a failed
  // level's vertices are rolled back by the caller).
  std::vector<std::vector<GridFace>> faces(parts.size());
  std::vector<size_t> dropped(parts.size(), 0);
  for (size_t j = 0; j < parts.size(); ++j) faces[j] = grid_faces(meshes[j], pool, dropped[j]);
  std::vector<EncodedSolid> solids(parts.size());
  tbb::parallel_for(size_t(0), parts.size(), with_thread_tag([&](size_t j) {
                      solids[j] = checked_solid(std::move(faces[j]), meshes[j].semantic_labels,
                                                pool.vertices(), pool.step(), lod, version);
                      solids[j].dropped_faces = dropped[j];
                    }));
  for (size_t j = 0; j < parts.size(); ++j) {
    e.check_seconds += solids[j].check_seconds;
    if (!solids[j].defect.empty()) {
      e.defect = "part " + std::to_string(j) + " is invalid on the output grid (" + solids[j].defect + ")";
      e.failed_part = static_cast<int>(j);
      // For a developer: the part that failed, before rounding (docs/reliability.md).
      if (const char* dir = std::getenv("MC_DUMP_GRID_DEFECTS"))
        mc::io::write_off(std::string(dir) + "/" + building + "-L" + std::to_string(i) + "-p" +
                              std::to_string(j) + (conforming ? "" : "-own") + ".off",
                          meshes[j]);
      return e;
    }
  }
  if (conforming) align_repaired_parts(solids, meshes, pool, lod, version);
  const auto t_overlap = std::chrono::steady_clock::now();
  std::tie(e.defect, e.failed_part) = first_overlap(solids, parts, pool, conforming, plain);
  e.check_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t_overlap).count();
  if (!e.defect.empty()) return e;
  stage_parts(building, i, threshold, parts, meshes, solids, e);
  return e;
}

// A level whose parts are the parts of the level encoded before it is encoded exactly as that one
// (the same meshes, vertices already in the pool, the same checks and repairs): its encoding is
// that level's under its own ids, level and neighbour ids. Most small buildings keep their parts
// over several levels (docs/benchmarks.md, "Speed").
}  // namespace

EncodedLevel relabelled(const EncodedLevel& previous, const std::string& building, size_t i, double threshold,
                        const std::vector<PartResult>& parts) {
  EncodedLevel e = previous;
  e.lv.index = i;
  e.lv.threshold = threshold;
  e.check_seconds = 0;
  for (size_t j = 0; j < e.staged.size(); ++j) {
    e.staged[j].id = part_id(building, i, j);
    json& a = e.staged[j].object["attributes"];
    a["morphcut_level"] = threshold;
    json neighbours = json::array();
    for (uint32_t n : parts[j].neighbours) neighbours.push_back(part_id(building, i, n));
    a["neighbours"] = std::move(neighbours);
  }
  return e;
}

namespace {

// A level's parts encoded on the output grid, as meshes that fit their neighbours exactly
// (level_part_meshes). When a part stays invalid after its own repairs (output/part_repair.hpp):
//   1. the level's vertices are clustered ever more coarsely (vertices within 1, 2, then 4 grid
//      steps become one) and the whole level is encoded again, so that every part sharing a
//      moved vertex moves with it;
//   2. each part is encoded from its own mesh (no vertex kept for a neighbour's corner): a kept
//      vertex rounded off its straight edge can force a sliver triangle that folds into the part.
//      Valid parts, but a neighbour's corner may then stand a fraction of a grid step inside it.
// On failure the pool is back at its mark and the first defect is reported.
EncodedLevel encode_parts_on_grid(const std::string& building, size_t i, double threshold,
                                  const std::vector<PartResult>& parts, const Preprocessed& pre,
                                  const std::string& lod, const std::string& version, VertexPool& pool) {
  const size_t mark = pool.mark();
  // The conforming attempts encode the same part meshes: built once (level_part_meshes is a third
  // of a level's encoding; a level that needs repairs is encoded up to five times here).
  const std::vector<PolygonMesh> meshes = level_part_meshes(pre, parts);
  EncodedLevel e =
      encode_level(building, i, threshold, parts, pre, lod, version, pool, true, false, true, &meshes);
  if (e.defect.empty()) return e;
  double spent = e.check_seconds;  // every attempt's checks count
  const std::string first = e.defect;
  const int first_part = e.failed_part;
  if (pool.can_cluster())
    for (int steps : {1, 2, 4}) {
      pool.rollback(mark);
      pool.cluster(steps, mark);
      e = encode_level(building, i, threshold, parts, pre, lod, version, pool, true, false, false, &meshes);
      pool.cluster(0, 0);
      spent += e.check_seconds;
      e.check_seconds = spent;
      if (e.defect.empty()) {
        e.grid_repair = "cluster " + std::to_string(steps);
        return e;
      }
    }
  // Vertices a fraction of a step from a face of their part moved away from it (part_merge.hpp).
  pool.rollback(mark);
  e = encode_level(building, i, threshold, parts, pre, lod, version, pool, true, /*separate=*/true, false,
                   &meshes);
  spent += e.check_seconds;
  e.check_seconds = spent;
  if (e.defect.empty()) {
    e.grid_repair = "separated";
    return e;
  }
  pool.rollback(mark);
  e = encode_level(building, i, threshold, parts, pre, lod, version, pool, false);
  e.check_seconds += spent;
  if (e.defect.empty()) {
    e.grid_repair = "non-conforming";
    return e;
  }
  pool.rollback(mark);
  e.defect = first;
  e.failed_part = first_part;
  return e;
}

}  // namespace

namespace {
// The most parts a level may lose to merges: a few (a sub-grid feature between two parts), not a
// level (a defect shared by many parts around one point, which each merge moves to the next
// part: the tile's wall-less variant merged 192 of 248 parts, re-encoding the level each time).
// Beyond it the level falls back, with its reason (docs/output-format.md §Repairs, step 6).
size_t max_merges(size_t parts) { return std::max<size_t>(4, parts / 16); }
}  // namespace

// encode_parts_on_grid, then, while a part still fails, that part merged into the neighbour it
// shares the largest face with and the level encoded again (output/part_merge.hpp): a level of
// fewer parts rather than another level, up to max_merges. On failure the first defect is
// reported.
EncodedLevel encode_level_on_grid(const std::string& building, size_t i, double threshold,
                                  const std::vector<PartResult>& parts, const Preprocessed& pre,
                                  const std::string& lod, const std::string& version, VertexPool& pool) {
  EncodedLevel e = encode_parts_on_grid(building, i, threshold, parts, pre, lod, version, pool);
  if (e.defect.empty() || parts.size() < 2) return e;
  const EncodedLevel first = e;
  double spent = e.check_seconds;
  std::vector<PartResult> current = parts;
  for (size_t merges = 1; merges <= max_merges(parts.size()) && current.size() > 1 && e.failed_part >= 0;
       ++merges) {
    const int k = largest_neighbour(level_part_meshes(pre, current), static_cast<size_t>(e.failed_part));
    if (k < 0) break;
    current = merge_parts(current, static_cast<size_t>(e.failed_part), static_cast<size_t>(k), pre);
    e = encode_parts_on_grid(building, i, threshold, current, pre, lod, version, pool);
    spent += e.check_seconds;
    e.check_seconds = spent;
    if (e.defect.empty()) {
      e.grid_repair = "merged " + std::to_string(merges) + " part(s)" +
                      (e.grid_repair.empty() ? std::string() : ", " + e.grid_repair);
      e.merged = std::move(current);
      return e;
    }
  }
  EncodedLevel out = first;
  out.check_seconds = spent;
  return out;
}

}  // namespace mc::pipeline
