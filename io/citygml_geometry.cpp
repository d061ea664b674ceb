#include "io/citygml_geometry.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

#include "io/citygml_remote.hpp"
#include "io/citygml_xml.hpp"

namespace mc::io::citygml {

using namespace gmlxml;

namespace {

// Deeper nesting than any sane geometry means an xlink cycle (a surface referring to itself).
constexpr int kMaxDepth = 32;
constexpr size_t kMaxNotes = 10;
constexpr size_t kMaxSrsNames = 8;  // enough to tell that a building's geometries disagree

// Whitespace- (or `sep`-) separated numbers; false on the first token that is not a finite number.
bool parse_numbers(std::string_view s, std::vector<double>& out, std::string& bad, char sep = 0) {
  size_t i = 0;
  auto is_sep = [&](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || (sep && c == sep); };
  while (i < s.size()) {
    while (i < s.size() && is_sep(s[i])) ++i;
    if (i >= s.size()) break;
    size_t j = i;
    while (j < s.size() && !is_sep(s[j])) ++j;
    double v = 0;
    const char* b = s.data() + i;
    const char* e = s.data() + j;
    if (*b == '+') ++b;  // from_chars does not take a leading '+', xsd:double does
    auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) {
      bad = std::string(s.substr(i, std::min<size_t>(j - i, 40)));
      return false;
    }
    out.push_back(v);
    i = j;
  }
  return true;
}

bool surface_member(const xmlNode* n) { return gml(n, "surfaceMember") || gml(n, "baseSurface"); }

}  // namespace

size_t GeometryReader::KeyHash::operator()(const Key& k) const {
  auto h = [](double d) { return std::hash<uint64_t>()(std::bit_cast<uint64_t>(d == 0 ? 0.0 : d)); };
  return h(k.x) ^ (h(k.y) * 0x9e3779b97f4a7c15ULL) ^ (h(k.z) * 0xc2b2ae3d27d4eb4fULL);
}

GeometryReader::GeometryReader(const xmlNode* building, const RemoteGeometry* remote)
    : root_(building), remote_(remote) {
  // Iterative walk: buildings can be deep, and the stack of the reader thread is not ours.
  std::vector<const xmlNode*> stack{building};
  while (!stack.empty()) {
    const xmlNode* n = stack.back();
    stack.pop_back();
    if (std::string id = gml_id(n); !id.empty()) by_id_.emplace(std::move(id), n);
    if (std::string srs = attr(n, "srsName"); !srs.empty()) {
      if (srs_name_.empty()) srs_name_ = srs;
      if (srs_names_.size() < kMaxSrsNames &&
          std::find(srs_names_.begin(), srs_names_.end(), srs) == srs_names_.end())
        srs_names_.push_back(std::move(srs));
    }
    // Children pushed in reverse: the first srsName in document order wins.
    std::vector<const xmlNode*> kids;
    for (const xmlNode* c = first_child(n); c; c = next_sibling(c)) kids.push_back(c);
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
}

void GeometryReader::note(std::string msg) {
  if (notes_.size() < kMaxNotes) notes_.push_back(std::move(msg));
}
void GeometryReader::fail(std::string msg) {
  if (fatal_.empty()) fatal_ = std::move(msg);
}

const xmlNode* GeometryReader::content(const xmlNode* property) {
  const std::string ref = href(property);
  if (ref.empty()) return first_child(property);
  if (ref[0] == '#') {
    const std::string id = ref.substr(1);
    auto it = by_id_.find(id);
    if (it != by_id_.end()) return it->second;
    if (remote_) {
      if (const xmlNode* n = remote_->find(id)) return n;
      if (remote_->dropped(id)) {
        note(
            "xlink:href \"" + ref +
            "\" names geometry outside this building that is not stored (the store of such targets is full); "
            "that surface is missing");
        return nullptr;
      }
    }
    note("xlink:href \"" + ref +
         "\" names no element of this building and no GML geometry elsewhere in the file; that surface is "
         "missing");
    return nullptr;
  }
  note("xlink:href \"" + ref + "\" refers outside this file; that surface is missing");
  return nullptr;
}

uint32_t GeometryReader::vertex(double x, double y, double z) {
  auto [it, added] = pool_.try_emplace(Key{x, y, z}, static_cast<uint32_t>(vertices_.size()));
  if (added) vertices_.push_back({x, y, z});
  return it->second;
}

// srsDimension on the coordinates or on the nearest geometry above them; GML's default is 3 here
// (CityGML geometry is 3D).
int GeometryReader::dimension(const xmlNode* el) const {
  for (const xmlNode* n = el; n && n->type == XML_ELEMENT_NODE; n = n->parent) {
    const std::string d = attr(n, "srsDimension");
    if (!d.empty()) return std::atoi(d.c_str());
    if (n == root_) break;
  }
  return 3;
}

bool GeometryReader::coordinates(const xmlNode* el, std::vector<double>& xyz) {
  std::string bad;
  std::vector<double> v;
  if (gml(el, "posList") || gml(el, "pos")) {
    const int dim = dimension(el);
    const char* what = gml(el, "pos") ? "gml:pos" : "gml:posList";
    if (dim == 2) {
      fail(std::string("2D coordinates (srsDimension 2 in ") + what + ") are not supported");
      return false;
    }
    if (dim != 3) {
      fail(std::string("srsDimension ") + std::to_string(dim) + " in " + what + " is not supported");
      return false;
    }
    const std::string s = text(el);
    if (!parse_numbers(s, v, bad)) {
      fail(std::string("broken ") + what + ": \"" + bad + "\" is not a number");
      return false;
    }
    if (gml(el, "pos") && v.size() == 2) {
      fail("2D coordinates (gml:pos with 2 values) are not supported");
      return false;
    }
    if (v.size() % 3 != 0 || (gml(el, "pos") && v.size() != 3)) {
      fail(std::string("broken ") + what + ": " + std::to_string(v.size()) + " values, not " +
           (gml(el, "pos") ? "3" : "a multiple of 3"));
      return false;
    }
  } else {  // gml:coordinates (GML 2 style): tuples separated by `ts`, values by `cs`
    const std::string cs = attr(el, "cs"), ts = attr(el, "ts"), dec = attr(el, "decimal");
    if ((!dec.empty() && dec != ".") || cs.size() > 1 || (!ts.empty() && ts != " ")) {
      fail("gml:coordinates with custom decimal/ts separators are not supported");
      return false;
    }
    const char sep = cs.empty() ? ',' : cs[0];
    const std::string s = text(el);
    for (size_t i = 0; i < s.size();) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i >= s.size()) break;
      size_t j = i;
      while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      const size_t before = v.size();
      if (!parse_numbers(std::string_view(s).substr(i, j - i), v, bad, sep)) {
        fail("broken gml:coordinates: \"" + bad + "\" is not a number");
        return false;
      }
      if (v.size() - before == 2) {
        fail("2D coordinates (gml:coordinates) are not supported");
        return false;
      }
      if (v.size() - before != 3) {
        fail("broken gml:coordinates: a tuple of " + std::to_string(v.size() - before) + " values");
        return false;
      }
      i = j;
    }
  }
  xyz.insert(xyz.end(), v.begin(), v.end());
  return true;
}

// A LinearRing as vertex indices: the closing point and immediate repeats dropped; empty on error.
std::vector<uint32_t> GeometryReader::ring(const xmlNode* el) {
  if (!gml(el, "LinearRing")) {
    note("ring type gml:" + std::string(local(el)) + " is not supported; its polygon is skipped");
    return {};
  }
  std::vector<double> xyz;
  for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
    if (gml(c, "posList") || gml(c, "pos") || gml(c, "coordinates")) {
      if (!coordinates(c, xyz)) return {};
    } else if (gml(c, "pointProperty") || gml(c, "pointRep")) {
      const xmlNode* p = content(c);
      const xmlNode* pos = p && gml(p, "Point") ? first_child(p) : nullptr;
      if (!pos || !coordinates(pos, xyz)) return {};
    }
  }
  std::vector<uint32_t> out;
  for (size_t i = 0; i + 2 < xyz.size(); i += 3) {
    const uint32_t v = vertex(xyz[i], xyz[i + 1], xyz[i + 2]);
    if (out.empty() || out.back() != v) out.push_back(v);
  }
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

std::optional<Polygon> GeometryReader::polygon(const xmlNode* el, bool flip) {
  Polygon p;
  p.source = el;
  bool have_exterior = false;
  for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
    const bool exterior = gml(c, "exterior") || gml(c, "outerBoundaryIs");
    if (!exterior && !gml(c, "interior") && !gml(c, "innerBoundaryIs")) continue;
    const xmlNode* r = first_child(c);
    if (!r) continue;
    std::vector<uint32_t> idx = ring(r);
    if (!fatal_.empty()) return std::nullopt;
    if (idx.size() < 3) {
      if (exterior) {
        note("a polygon" + (gml_id(el).empty() ? std::string() : " \"" + gml_id(el) + "\"") +
             " has fewer than 3 distinct points; skipped");
        return std::nullopt;
      }
      continue;  // a degenerate hole changes nothing
    }
    if (flip) std::reverse(idx.begin(), idx.end());
    if (exterior) {
      have_exterior = true;
      p.rings.insert(p.rings.begin(), std::move(idx));
    } else {
      p.rings.push_back(std::move(idx));
    }
  }
  if (!have_exterior) return std::nullopt;
  return p;
}

void GeometryReader::member_surfaces(const xmlNode* member, bool flip, std::vector<Polygon>& out, int depth) {
  if (gml(member, "surfaceMembers") || gml(member, "patches") || gml(member, "polygonPatches") ||
      gml(member, "trianglePatches")) {
    for (const xmlNode* c = first_child(member); c; c = next_sibling(c)) surfaces(c, flip, out, depth + 1);
  } else if (const xmlNode* c = content(member)) {
    surfaces(c, flip, out, depth + 1);
  }
}

void GeometryReader::surfaces(const xmlNode* el, bool flip, std::vector<Polygon>& out, int depth) {
  if (!fatal_.empty()) return;
  if (depth > kMaxDepth) {
    note("surfaces nested too deeply (an xlink cycle?); skipped");
    return;
  }
  const std::string_view name = local(el);
  if (!is_gml_ns(ns_uri(el))) {
    note("surface element " + std::string(name) + " is not GML; skipped");
    return;
  }
  if (name == "Polygon" || name == "PolygonPatch" || name == "Triangle" || name == "Rectangle") {
    if (auto p = polygon(el, flip)) out.push_back(std::move(*p));
  } else if (name == "OrientableSurface") {
    const bool minus = attr(el, "orientation") == "-";
    for (const xmlNode* c = first_child(el); c; c = next_sibling(c))
      if (surface_member(c)) member_surfaces(c, flip != minus, out, depth);
  } else if (name == "MultiSurface" || name == "CompositeSurface" || name == "Shell" || name == "Surface" ||
             name == "PolyhedralSurface" || name == "TriangulatedSurface" || name == "Tin") {
    for (const xmlNode* c = first_child(el); c; c = next_sibling(c))
      if (surface_member(c) || gml(c, "surfaceMembers") || gml(c, "patches") || gml(c, "polygonPatches") ||
          gml(c, "trianglePatches"))
        member_surfaces(c, flip, out, depth);
  } else {
    note("geometry gml:" + std::string(name) + " is not a surface; skipped");
  }
}

std::optional<Solid> GeometryReader::solid(const xmlNode* el, int depth) {
  Solid s;
  for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
    const bool exterior = gml(c, "exterior");
    if (!exterior && !gml(c, "interior")) continue;
    std::vector<Polygon> shell;
    if (const xmlNode* shell_el = content(c)) surfaces(shell_el, false, shell, depth + 1);
    if (shell.empty()) {
      if (exterior) return std::nullopt;
      continue;
    }
    if (exterior) s.shells.insert(s.shells.begin(), std::move(shell));
    else s.shells.push_back(std::move(shell));
  }
  if (s.shells.empty()) return std::nullopt;
  return s;
}

void GeometryReader::solids(const xmlNode* el, std::vector<Solid>& out, int depth) {
  if (!fatal_.empty() || depth > kMaxDepth) return;
  if (gml(el, "Solid")) {
    if (auto s = solid(el, depth)) out.push_back(std::move(*s));
    return;
  }
  if (!gml(el, "CompositeSolid") && !gml(el, "MultiSolid")) {
    note("solid member gml:" + std::string(local(el)) + " is not a solid; skipped");
    return;
  }
  for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
    if (gml(c, "solidMember")) {
      if (const xmlNode* m = content(c)) solids(m, out, depth + 1);
    } else if (gml(c, "solidMembers")) {
      for (const xmlNode* m = first_child(c); m; m = next_sibling(m)) solids(m, out, depth + 1);
    }
  }
}

std::optional<Geometry> GeometryReader::read(const xmlNode* property) {
  const xmlNode* el = content(property);
  if (!el) return std::nullopt;
  Geometry g;
  if (gml(el, "Solid") || gml(el, "CompositeSolid") || gml(el, "MultiSolid")) {
    g.type = std::string(local(el));
    solids(el, g.solids, 0);
    if (g.type == "Solid" && g.solids.size() != 1) return std::nullopt;
    if (g.solids.empty()) return std::nullopt;
  } else {
    g.type = gml(el, "CompositeSurface") ? "CompositeSurface" : "MultiSurface";
    surfaces(el, false, g.surfaces, 0);
    if (g.surfaces.empty()) return std::nullopt;
  }
  if (!fatal_.empty()) return std::nullopt;
  return g;
}

std::vector<Polygon> GeometryReader::read_surfaces(const xmlNode* property) {
  std::vector<Polygon> out;
  if (const xmlNode* el = content(property)) surfaces(el, false, out, 0);
  return out;
}

}  // namespace mc::io::citygml
