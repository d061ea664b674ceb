// The pull loop: libxml2's xmlTextReader walks the document node by node; a Building directly
// under a city object member is expanded (its subtree only), converted, and skipped over, which
// lets the reader free it. Everything else at that level is skipped without being built. A first
// pass (citygml_prescan) counts the buildings and finds xlinks between buildings beforehand.
#include "io/citygml_reader.hpp"

#include <libxml/xmlreader.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "io/citygml_building.hpp"
#include "io/citygml_crs.hpp"
#include "io/citygml_input.hpp"
#include "io/citygml_prescan.hpp"
#include "io/citygml_remote.hpp"
#include "io/citygml_xml.hpp"
#include "io/cityjson_common.hpp"
#include "io/crs.hpp"

namespace mc::io {

using nlohmann::json;
using namespace gmlxml;

namespace {

std::optional<mc::Vec3> parse_point(const std::string& s) {
  double v[3] = {0, 0, 0};
  int n = 0;
  const char* p = s.c_str();
  char* end = nullptr;
  while (n < 3) {
    const double d = std::strtod(p, &end);
    if (end == p || !std::isfinite(d)) break;
    v[n++] = d;
    p = end;
  }
  if (n < 2) return std::nullopt;
  return mc::Vec3{v[0], v[1], v[2]};
}

}  // namespace

struct CityGmlReader::Impl {
  enum class Move { Read, Skip };

  explicit Impl(const std::string& p)
      : path(p), input(std::make_unique<citygml::XmlInput>(p)), rd(input->reader()) {
    int r;
    while ((r = read(Move::Read)) == 1 && xmlTextReaderNodeType(rd) != XML_READER_TYPE_ELEMENT) {}
    if (r != 1) throw ReadError(p + ": no XML root element");
    root();
    // The first pass: the building count, and the geometry shared across buildings that the
    // main pass stores beforehand (only when there is any: it costs one more read of the file).
    prescan = citygml::prescan(p);
    if (!prescan.remote_ids.empty()) {
      remote.collect(p, std::move(prescan.remote_ids));
      prescan.remote_ids.clear();
      for (auto& s : remote.problems()) problems.push_back(std::move(s));
    }
    if (prescan.remote_ids_dropped)
      problems.push_back(
          std::to_string(prescan.remote_ids_dropped) +
          " xlink targets outside their building are not resolved: beyond the first pass's bound (" +
          std::to_string(citygml::Prescan::kMaxRemoteIds) + " ids or " +
          std::to_string(citygml::Prescan::kMaxRemoteIdBytes >> 20) + " MB of them)");
    pending = scan();  // the header needs the first building when the file has no envelope
    make_header();
    if (pending) check_srs(*pending);
  }

  std::string_view reader_local() const {
    const xmlChar* s = xmlTextReaderConstLocalName(rd);
    return s ? std::string_view(reinterpret_cast<const char*>(s)) : std::string_view();
  }
  std::string_view reader_uri() const {
    const xmlChar* s = xmlTextReaderConstNamespaceUri(rd);
    return s ? std::string_view(reinterpret_cast<const char*>(s)) : std::string_view();
  }
  std::string reader_qualified_name() const {
    const xmlChar* s = xmlTextReaderConstName(rd);
    return s ? reinterpret_cast<const char*>(s) : "";
  }

  int read(Move m) {
    const int r = m == Move::Skip ? xmlTextReaderNext(rd) : xmlTextReaderRead(rd);
    if (r < 0) fail();
    return r;
  }
  [[noreturn]] void fail() {
    throw ReadError(path + ": " + input->failure() + " (after " + std::to_string(buildings) + " buildings)");
  }
  xmlNode* expand() {
    xmlNode* n = xmlTextReaderExpand(rd);
    if (!n) fail();
    return n;
  }

  // The version from the root CityModel's namespace or, when it has none (an exporter that
  // declares no default namespace), from the CityGML namespaces declared on it.
  void root() {
    const std::string_view uri = reader_uri(), name = reader_local();
    if (name == "CityModel" && is_core_ns(uri)) {
      version = citygml_version(uri);
      return;
    }
    const std::string expected = ", expected a CityGML 1.0/2.0/3.0 CityModel";
    if (name != "CityModel" || !uri.empty())
      throw ReadError(path + ": not CityGML: the root element is {" + std::string(uri) + "}" +
                      std::string(name) + expected);
    std::map<std::string, std::vector<std::string>> declared;  // version -> its namespaces
    for (const xmlNs* ns = xmlTextReaderCurrentNode(rd)->nsDef; ns; ns = ns->next) {
      const std::string_view href = ns->href ? reinterpret_cast<const char*>(ns->href) : "";
      if (const std::string_view v = citygml_version(href); !v.empty())
        declared[std::string(v)].emplace_back(href);
    }
    if (declared.empty())
      throw ReadError(path +
                      ": not CityGML: the root element is {}CityModel (no namespace) and declares no CityGML "
                      "namespace" +
                      expected);
    auto most = declared.begin();  // the version most namespaces have (the newer one on a tie)
    for (auto it = declared.begin(); it != declared.end(); ++it)
      if (it->second.size() >= most->second.size()) most = it;
    version = most->first;
    std::string names;
    for (size_t i = 0; i < most->second.size() && i < 3; ++i) names += (i ? ", " : "") + most->second[i];
    if (most->second.size() > 3) names += ", ...";
    problems.push_back("the root element CityModel has no namespace: read as CityGML " + version +
                       ", the version of the CityGML namespaces declared on it (" + names + ")");
    if (declared.size() > 1)
      problems.push_back("the root element declares CityGML namespaces of " +
                         std::to_string(declared.size()) + " versions; read as CityGML " + version);
  }

  // Advances to the next building and converts it; nullopt at the end of the document.
  std::optional<citygml::ConvertedBuilding> scan() {
    while (!ended) {
      const int r = read(next_move);
      next_move = Move::Read;
      if (r == 0) {
        ended = true;
        finish();
        break;
      }
      if (xmlTextReaderNodeType(rd) != XML_READER_TYPE_ELEMENT) continue;
      const int depth = xmlTextReaderDepth(rd);
      const std::string_view name = reader_local(), uri = reader_uri();
      if (depth == 1) {
        next_move = Move::Skip;
        switch (top_level(uri, name)) {
          case Top::UnqualifiedEnvelope:
            ++unqualified[std::string(name)];
            [[fallthrough]];
          case Top::Envelope:
            envelope(expand());
            break;
          case Top::Name:
            if (title.empty()) title = trim(text(expand()));
            break;
          case Top::Metadata:  // gml:description and other metadata of the model
            break;
          case Top::UnqualifiedMember:
            ++unqualified[std::string(name)];
            next_move = Move::Read;  // a member: read on into it
            break;
          case Top::Member:
            next_move = Move::Read;
            break;
          case Top::Ade:
            ade.add(reader_qualified_name(), uri);
            break;
          case Top::Other:
            ++skipped_top[std::string(name)];  // appearanceMember (global appearances), ...
            break;
        }
        continue;
      }
      next_move = Move::Skip;
      if (depth != 2) continue;
      if (!(is_citygml_ns(uri) && name == "Building")) {
        if (is_ade_ns(uri)) ade.add(reader_qualified_name(), uri);
        else ++skipped[std::string(name)];
        continue;
      }
      const xmlNode* building = expand();  // "after N buildings" counts those handed out
      ++buildings;
      citygml::ConvertedBuilding b =
          citygml::convert_building(building, "building-" + std::to_string(buildings), &remote);
      ade.merge(b.ade);
      return b;
    }
    return std::nullopt;
  }

  void envelope(const xmlNode* bounded_by) {
    const xmlNode* env = first_child(bounded_by);
    if (!env || !gml(env, "Envelope")) return;
    envelope_srs = attr(env, "srsName");
    for (const xmlNode* c = first_child(env); c; c = next_sibling(c))
      if ((gml(c, "lowerCorner") || gml(c, "pos")) && !lower) lower = parse_point(text(c));
  }

  // A building whose srsNames (on it or on any of its geometries) are not the file's.
  void check_srs(const citygml::ConvertedBuilding& b) {
    if (reference.empty()) return;
    for (const auto& srs : b.srs_names)
      if (citygml::reference_system(srs) != reference) {
        if (srs_mismatches++ == 0) srs_example = b.feature.id + " has srsName \"" + srs + "\"";
        return;
      }
  }

  // CRS: the envelope's srsName, else the first one inside a building (on it or on a geometry).
  void make_header() {
    std::string srs = !envelope_srs.empty() ? envelope_srs : prescan.first_srs;
    if (srs.empty() && pending) srs = pending->srs_name;  // the first pass stopped before it
    reference = citygml::reference_system(srs);
    no_srs = srs.empty();  // said at the end, with the other findings about the whole file
    if (!srs.empty() && reference.empty())
      problems.push_back("srsName \"" + srs +
                         "\" is not an EPSG reference system; the output has no referenceSystem");
    // Millimetres from a whole-metre corner: the CityJSON quantisation the writer applies.
    mc::Vec3 corner{0, 0, 0};
    if (lower) {
      corner = *lower;
    } else if (pending && !pending->feature.vertices.empty()) {
      corner = pending->feature.vertices[0];
      for (const auto& v : pending->feature.vertices)
        corner = {std::min(corner.x, v.x), std::min(corner.y, v.y), std::min(corner.z, v.z)};
    }
    json root = {{"type", "CityJSON"},
                 {"version", "2.0"},
                 {"transform",
                  {{"scale", {0.001, 0.001, 0.001}},
                   {"translate", {std::floor(corner.x), std::floor(corner.y), std::floor(corner.z)}}}}};
    json metadata = json::object();
    if (!reference.empty()) metadata["referenceSystem"] = reference;
    if (!title.empty()) metadata["title"] = title;
    if (!metadata.empty()) root["metadata"] = std::move(metadata);
    header.version = "2.0";
    header.crs = parse_crs(root);
    header.coords = coordinate_system(header.crs, /*axis_order_of_crs=*/true, &header.coords_note);
    header.root = std::move(root);
  }

  static std::string listed(const std::map<std::string, size_t>& m, size_t& total) {
    std::string s;
    total = 0;
    for (const auto& [name, n] : m) {
      s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + name;
      total += n;
    }
    return s;
  }

  void finish() {
    size_t total = 0;
    if (!unqualified.empty()) {
      const std::string s = listed(unqualified, total);
      problems.push_back(
          "read " + std::to_string(total) +
          " children of CityModel without a namespace as CityGML/GML members and envelope: " + s);
    }
    if (!skipped.empty()) {
      const std::string s = listed(skipped, total);
      problems.push_back("skipped " + std::to_string(total) + " city objects that are not buildings: " + s);
    }
    if (!skipped_top.empty()) {
      const std::string s = listed(skipped_top, total);
      problems.push_back("not carried: " + std::to_string(total) + " top-level elements (" + s + ")");
    }
    if (!ade.empty()) problems.push_back(ade.summary());
    if (no_srs)
      problems.push_back(
          "no srsName in the file: coordinates are taken as they are (a metric CRS is assumed)");
    if (srs_mismatches)
      problems.push_back(std::to_string(srs_mismatches) +
                         " buildings have an srsName other than the file's (" + srs_example +
                         "); coordinates are used as they are");
  }

  std::string path;
  std::unique_ptr<citygml::XmlInput> input;
  xmlTextReaderPtr rd;
  std::string version, title;
  Move next_move = Move::Read;
  bool ended = false, no_srs = false;
  size_t buildings = 0, srs_mismatches = 0;
  Header header;
  std::vector<std::string> problems;
  std::map<std::string, size_t> skipped, skipped_top, unqualified;
  citygml::AdeTally ade;
  citygml::Prescan prescan;
  citygml::RemoteGeometry remote;
  std::optional<citygml::ConvertedBuilding> pending;
  std::string envelope_srs, reference, srs_example;
  std::optional<mc::Vec3> lower;
};

CityGmlReader::CityGmlReader(const std::string& path) : impl_(std::make_unique<Impl>(path)) {}
CityGmlReader::~CityGmlReader() = default;

const Header& CityGmlReader::header() const { return impl_->header; }
bool CityGmlReader::next(Feature& out) {
  if (impl_->pending) {
    out = std::move(impl_->pending->feature);
    impl_->pending.reset();
    return true;
  }
  auto b = impl_->scan();
  if (!b) return false;
  impl_->check_srs(*b);
  out = std::move(b->feature);
  return true;
}
const std::vector<std::string>& CityGmlReader::problems() const { return impl_->problems; }
std::string CityGmlReader::format() const { return "CityGML " + impl_->version; }
std::optional<size_t> CityGmlReader::feature_count() const {
  if (!impl_->prescan.complete) return std::nullopt;
  return impl_->prescan.buildings;
}
const std::map<std::string, size_t>& CityGmlReader::skipped_objects() const { return impl_->skipped; }

}  // namespace mc::io
