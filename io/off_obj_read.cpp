// OFF/OBJ readers: line based, so that the variable-length extras of real files (NOFF normals,
// per-face colours) are ignored without miscounting tokens.
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "io/off_obj.hpp"

namespace mc::io {

namespace {

struct Lines {
  explicit Lines(const std::string& path) : path(path), in(path, std::ios::binary) {
    if (!in) throw ReadError(path + ": cannot open");
  }
  // Next non-empty line split into tokens, '#' comments removed; false at end of file.
  bool next(std::vector<std::string_view>& tokens) {
    while (std::getline(in, line)) {
      ++number;
      if (auto c = line.find('#'); c != std::string::npos) line.resize(c);
      tokens.clear();
      size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        size_t j = i;
        while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
        if (j > i) tokens.emplace_back(line.data() + i, j - i);
        i = j;
      }
      if (!tokens.empty()) return true;
    }
    return false;
  }
  ReadError error(const std::string& why) const {
    return ReadError(path + ":" + std::to_string(number) + ": " + why);
  }
  double real(std::string_view t) const {
    double v = 0;
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      throw error("\"" + std::string(t) + "\" is not a number");
    if (!std::isfinite(v)) throw error("non-finite coordinate \"" + std::string(t) + "\"");
    return v;
  }
  long long integer(std::string_view t) const {
    long long v = 0;
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      throw error("\"" + std::string(t) + "\" is not an integer");
    return v;
  }

  std::string path;
  std::ifstream in;
  std::string line;
  size_t number = 0;
};

bool is_off_header(std::string_view t) {
  // [ST][C][N][4][n]OFF; the 4D variants are rejected later.
  if (t.size() < 3 || t.substr(t.size() - 3) != "OFF") return false;
  std::string_view p = t.substr(0, t.size() - 3);
  if (p.substr(0, 2) == "ST") p.remove_prefix(2);
  for (char c : {'C', 'N', '4', 'n'})
    if (!p.empty() && p.front() == c) p.remove_prefix(1);
  return p.empty();
}

// A face of three or more vertices joins the mesh; a shorter one is skipped with a problem line.
void add_face(mc::PolygonMesh& mesh, std::vector<uint32_t> ring, int32_t label, const Lines& lines,
              std::vector<std::string>* problems) {
  if (ring.size() >= 3) {
    mesh.faces.push_back(mc::Polygon{{std::move(ring)}, label});
  } else if (problems) {
    problems->push_back(lines.path + ":" + std::to_string(lines.number) +
                        ": face with fewer than 3 vertices skipped");
  }
}

}  // namespace

mc::PolygonMesh read_off(const std::string& path, std::vector<std::string>* problems) {
  Lines lines(path);
  std::vector<std::string_view> tok;
  if (!lines.next(tok)) throw ReadError(path + ": empty file (expected an OFF header)");
  size_t first = 0;
  if (is_off_header(tok[0])) {
    if (tok[0].find('4') != std::string_view::npos)
      throw lines.error("4D OFF (" + std::string(tok[0]) + ") is not supported");
    if (tok.size() > 1) {
      first = 1;  // counts on the header line: "OFF 8 6 0"
    } else if (!lines.next(tok)) {
      throw lines.error("missing the vertex/face counts line");
    }
  } else if (!std::isdigit(static_cast<unsigned char>(tok[0][0]))) {
    throw lines.error("not an OFF file (header \"" + std::string(tok[0]) + "\")");
  }
  if (tok.size() < first + 2) throw lines.error("expected \"<vertices> <faces> [edges]\"");
  const long long nv = lines.integer(tok[first]), nf = lines.integer(tok[first + 1]);
  if (nv < 0 || nf < 0) throw lines.error("negative vertex or face count");
  mc::PolygonMesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(std::min<long long>(nv, 1 << 24)));
  for (long long i = 0; i < nv; ++i) {
    if (!lines.next(tok))
      throw ReadError(path + ": file ends after " + std::to_string(i) + " of " + std::to_string(nv) +
                      " vertices");
    if (tok.size() < 3) throw lines.error("a vertex needs 3 coordinates");
    mesh.vertices.emplace_back(lines.real(tok[0]), lines.real(tok[1]), lines.real(tok[2]));
  }
  for (long long i = 0; i < nf; ++i) {
    if (!lines.next(tok))
      throw ReadError(path + ": file ends after " + std::to_string(i) + " of " + std::to_string(nf) +
                      " faces");
    const long long n = lines.integer(tok[0]);
    if (n < 0 || static_cast<size_t>(n) + 1 > tok.size())
      throw lines.error("face declares " + std::to_string(n) + " vertices but lists " +
                        std::to_string(tok.size() - 1));
    std::vector<uint32_t> ring;
    for (long long k = 1; k <= n; ++k) {
      const long long idx = lines.integer(tok[k]);
      if (idx < 0 || idx >= nv)
        throw lines.error("vertex index " + std::to_string(idx) + " out of range (" + std::to_string(nv) +
                          " vertices)");
      ring.push_back(static_cast<uint32_t>(idx));
    }
    add_face(mesh, std::move(ring), -1, lines, problems);
  }
  return mesh;
}

mc::PolygonMesh read_obj(const std::string& path, std::vector<std::string>* problems) {
  Lines lines(path);
  std::vector<std::string_view> tok;
  mc::PolygonMesh mesh;
  int32_t label = -1;
  while (lines.next(tok)) {
    if (tok[0] == "v") {
      if (tok.size() < 4) throw lines.error("a vertex needs 3 coordinates");
      mesh.vertices.emplace_back(lines.real(tok[1]), lines.real(tok[2]), lines.real(tok[3]));
    } else if (tok[0] == "f") {
      std::vector<uint32_t> ring;
      for (size_t k = 1; k < tok.size(); ++k) {
        const std::string_view t = tok[k].substr(0, tok[k].find('/'));
        long long idx = lines.integer(t);
        const auto nv = static_cast<long long>(mesh.vertices.size());
        if (idx < 0) idx += nv;
        else --idx;  // 1-based; negative counts back from the last vertex
        if (idx < 0 || idx >= nv)
          throw lines.error("vertex reference " + std::string(t) + " out of range (" + std::to_string(nv) +
                            " vertices so far)");
        ring.push_back(static_cast<uint32_t>(idx));
      }
      add_face(mesh, std::move(ring), label, lines, problems);
    } else if (tok[0] == "usemtl") {
      label = (tok.size() < 2 || tok[1] == "none") ? -1 : mesh.label_index(std::string(tok[1]));
    }
  }
  return mesh;
}

}  // namespace mc::io
