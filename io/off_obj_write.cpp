#include <cstdio>
#include <limits>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/off_obj.hpp"

namespace mc::io {

namespace {

// Shortest text that reads back to the same double.
void put_real(std::ostream& o, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  o << buf;
}

template <class Body>
void write_atomically(const std::string& path, Body body) {
  try {
    AtomicFile file(path);
    body(file.stream());
    file.commit();
  } catch (const std::system_error& e) { throw WriteError(path + ": " + e.what()); }
}

}  // namespace

std::vector<uint32_t> bridge_holes(const mc::PolygonMesh& mesh, const mc::Polygon& face) {
  if (face.rings.empty()) return {};
  std::vector<uint32_t> ring = face.rings[0];
  for (size_t h = 1; h < face.rings.size(); ++h) {
    const auto& hole = face.rings[h];
    if (hole.empty() || ring.empty()) continue;
    size_t bi = 0, bj = 0;
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < ring.size(); ++i)
      for (size_t j = 0; j < hole.size(); ++j) {
        const double d = mc::norm(mesh.vertices[ring[i]] - mesh.vertices[hole[j]]);
        if (d < best) best = d, bi = i, bj = j;
      }
    std::vector<uint32_t> joined(ring.begin(), ring.begin() + static_cast<long>(bi) + 1);
    for (size_t k = 0; k <= hole.size(); ++k) joined.push_back(hole[(bj + k) % hole.size()]);
    joined.insert(joined.end(), ring.begin() + static_cast<long>(bi), ring.end());
    ring = std::move(joined);
  }
  return ring;
}

void write_off(const std::string& path, const mc::PolygonMesh& mesh, const std::vector<Rgb>& face_colours) {
  if (!face_colours.empty() && face_colours.size() != mesh.faces.size())
    throw WriteError(path + ": " + std::to_string(face_colours.size()) + " face colours for " +
                     std::to_string(mesh.faces.size()) + " faces");
  write_atomically(path, [&](std::ostream& o) {
    o << "OFF\n" << mesh.vertices.size() << ' ' << mesh.faces.size() << " 0\n";
    for (const auto& v : mesh.vertices) {
      put_real(o, v.x), o << ' ', put_real(o, v.y), o << ' ', put_real(o, v.z), o << '\n';
    }
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
      const auto ring = bridge_holes(mesh, mesh.faces[f]);
      o << ring.size();
      for (uint32_t i : ring) o << ' ' << i;
      if (!face_colours.empty())
        o << "  " << int(face_colours[f][0]) << ' ' << int(face_colours[f][1]) << ' '
          << int(face_colours[f][2]);
      o << '\n';
    }
  });
}

void write_obj(const std::string& path, const mc::PolygonMesh& mesh) {
  write_atomically(path, [&](std::ostream& o) {
    o << "# morphcut-city polygon mesh\n";
    for (const auto& v : mesh.vertices) {
      o << "v ", put_real(o, v.x), o << ' ', put_real(o, v.y), o << ' ', put_real(o, v.z), o << '\n';
    }
    int32_t current = -1;
    for (const auto& face : mesh.faces) {
      if (face.semantic != current) {
        current = face.semantic;
        const bool named = current >= 0 && static_cast<size_t>(current) < mesh.semantic_labels.size();
        o << "usemtl " << (named ? mesh.semantic_labels[current] : std::string("none")) << '\n';
      }
      o << 'f';
      for (uint32_t i : bridge_holes(mesh, face)) o << ' ' << i + 1;
      o << '\n';
    }
  });
}

}  // namespace mc::io
