#include "output/part_objects.hpp"

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <chrono>
#include <cstring>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "output/part_repair.hpp"

namespace mc::output {

using nlohmann::json;

int64_t VertexPool::add(const Vec3& metric) {
  const Vec3 v = frame_.to_file(metric);
  // Grid coordinates: the integers the writer will emit (or the exact doubles without transform).
  const double s[3] = {t_.scale.x, t_.scale.y, t_.scale.z},
               o[3] = {t_.translate.x, t_.translate.y, t_.translate.z};
  const double c[3] = {v.x, v.y, v.z};
  int64_t q[3];
  Vec3 snapped = v;
  if (t_.present) {
    double r[3];
    for (int i = 0; i < 3; ++i) {
      q[i] = std::llround((c[i] - o[i]) / s[i]);
      r[i] = static_cast<double>(q[i]) * s[i] + o[i];
    }
    snapped = {r[0], r[1], r[2]};
    if (cluster_ > 0) {
      // The nearest vertex of this level within the cluster box (smallest id on a tie).
      int64_t best = -1;
      double best_d = std::numeric_limits<double>::infinity();
      for (int64_t dx = -cluster_; dx <= cluster_; ++dx)
        for (int64_t dy = -cluster_; dy <= cluster_; ++dy)
          for (int64_t dz = -cluster_; dz <= cluster_; ++dz) {
            auto it = index_.find({q[0] + dx, q[1] + dy, q[2] + dz});
            if (it == index_.end() || it->second < static_cast<int64_t>(cluster_from_)) continue;
            const double d = static_cast<double>(dx * dx + dy * dy + dz * dz);
            if (d < best_d || (d == best_d && it->second < best)) best = it->second, best_d = d;
          }
      if (best >= 0) return best;
    }
  } else {
    // No transform: dedupe exact duplicates only (bit patterns of the doubles).
    for (int i = 0; i < 3; ++i) {
      double d = c[i] == 0 ? 0.0 : c[i];
      std::memcpy(&q[i], &d, sizeof d);
    }
  }
  auto [it, fresh] = index_.try_emplace({q[0], q[1], q[2]}, static_cast<int64_t>(out_.size()));
  if (fresh) {
    out_.push_back(snapped);
    if (!frame_.identity()) metric_.push_back(frame_.to_metric(snapped));
  }
  return it->second;
}

void VertexPool::rollback(size_t mark) {
  for (auto it = index_.begin(); it != index_.end();)
    it = it->second >= static_cast<int64_t>(mark) ? index_.erase(it) : std::next(it);
  out_.resize(std::min(out_.size(), mark));
  if (!frame_.identity()) metric_.resize(out_.size());
}

std::vector<GridFace> grid_faces(const PolygonMesh& part, VertexPool& pool, size_t& dropped) {
  std::vector<int64_t> vid(part.vertices.size(), -1);
  auto id_of = [&](uint32_t v) {
    if (vid[v] < 0) vid[v] = pool.add(part.vertices[v]);
    return vid[v];
  };
  std::vector<GridFace> faces;
  for (const Polygon& f : part.faces) {
    GridFace g;
    g.semantic = f.semantic;
    g.neighbour = f.neighbour;
    for (size_t r = 0; r < f.rings.size(); ++r) {
      std::vector<int64_t> ring;
      for (uint32_t v : f.rings[r]) {
        if (v >= part.vertices.size()) throw std::runtime_error("part mesh refers to a missing vertex");
        const int64_t id = id_of(v);
        if (ring.empty() || ring.back() != id) ring.push_back(id);
      }
      while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
      if (ring.size() >= 3) g.rings.push_back(std::move(ring));
      else if (r == 0) break;  // the outer ring collapsed: the whole face is gone
    }
    if (g.rings.empty()) {
      ++dropped;
      continue;
    }
    faces.push_back(std::move(g));
  }
  return faces;
}

EncodedSolid checked_solid(std::vector<GridFace> faces, const std::vector<std::string>& semantic_labels,
                           const std::vector<Vec3>& pool, double step, const std::string& lod,
                           const std::string& version) {
  EncodedSolid out;
  const auto t0 = std::chrono::steady_clock::now();
  const size_t bent = triangulate_bent_shared_faces(faces, pool);
  PartRepair checked = check_and_repair(std::move(faces), pool, step);
  out.check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.defect = std::move(checked.defect);
  out.repaired = checked.repaired;
  out.triangles = std::move(checked.shell);
  out.split_faces = checked.split_faces + bent;
  out.faces = std::move(checked.faces);
  write_solid(out, semantic_labels, lod, version);
  return out;
}

EncodedSolid encode_solid(const PolygonMesh& part, const std::string& lod, const std::string& version,
                          VertexPool& pool) {
  size_t dropped = 0;
  std::vector<GridFace> faces = grid_faces(part, pool, dropped);
  EncodedSolid out =
      checked_solid(std::move(faces), part.semantic_labels, pool.vertices(), pool.step(), lod, version);
  out.dropped_faces = dropped;
  return out;
}

void write_solid(EncodedSolid& solid, const std::vector<std::string>& semantic_labels, const std::string& lod,
                 const std::string& version) {
  json surfaces = json::array(), values = json::array(), boundaries = json::array();
  std::vector<int> surface_of_label(semantic_labels.size(), -1);
  solid.shell.clear();
  for (const GridFace& f : solid.faces) {
    json value = nullptr;
    if (f.semantic >= 0 && static_cast<size_t>(f.semantic) < semantic_labels.size()) {
      int& s = surface_of_label[f.semantic];
      if (s < 0) {
        s = static_cast<int>(surfaces.size());
        surfaces.push_back({{"type", semantic_labels[f.semantic]}});
      }
      value = s;
    }
    values.push_back(value);
    boundaries.push_back(f.rings);
    solid.shell.push_back(f.rings);
  }
  solid.geometry = {{"type", "Solid"}};
  if (version == "1.0") solid.geometry["lod"] = std::strtod(lod.c_str(), nullptr);
  else solid.geometry["lod"] = lod;
  solid.geometry["boundaries"] = json::array({boundaries});
  if (!surfaces.empty())
    solid.geometry["semantics"] = {{"surfaces", surfaces}, {"values", json::array({values})}};
}

}  // namespace mc::output
