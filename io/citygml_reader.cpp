// The pull loop: libxml2's xmlTextReader walks the document node by node; a Building directly
// under a city object member is expanded (its subtree only), converted, and skipped over, which
// lets the reader free it. Everything else at that level is skipped without being built.
#include "io/citygml_reader.hpp"

#include <libxml/xmlreader.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "io/citygml_building.hpp"
#include "io/citygml_crs.hpp"
#include "io/citygml_xml.hpp"
#include "io/cityjson_common.hpp"
#include "io/crs.hpp"

namespace mc::io {

using nlohmann::json;
using namespace gmlxml;

namespace {

// "http://www.opengis.net/citygml/2.0" -> "2.0"; empty for anything else.
std::string core_version(std::string_view uri) {
  for (const char* v : {"1.0", "2.0", "3.0"})
    if (uri == std::string("http://www.opengis.net/citygml/") + v) return v;
  return "";
}

void on_xml_error(void* ctx, xmlErrorPtr e) {
  auto* first = static_cast<std::string*>(ctx);
  if (!first->empty() || !e || e->level < XML_ERR_ERROR) return;
  std::string msg = e->message ? e->message : "XML error";
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
  *first = "line " + std::to_string(e->line) + ": " + msg;
}

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

  explicit Impl(const std::string& p) : path(p) {
    if (FILE* f = std::fopen(p.c_str(), "rb")) {
      std::fclose(f);
    } else {
      throw ReadError(p + ": cannot open: " + std::strerror(errno));
    }
    // NONET: never fetch schemas or DTDs; HUGE: real posLists can exceed libxml2's default text
    // limits; COMPACT: smaller text nodes.
    rd = xmlReaderForFile(p.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_COMPACT);
    if (!rd) throw ReadError(p + ": cannot open as XML");
    xmlTextReaderSetStructuredErrorHandler(rd, on_xml_error, &first_error);
    try {
      int r;
      while ((r = read(Move::Read)) == 1 && xmlTextReaderNodeType(rd) != XML_READER_TYPE_ELEMENT) {}
      if (r != 1) throw ReadError(p + ": no XML root element");
      const std::string_view uri = reader_uri();
      version = core_version(uri);
      if (reader_local() != "CityModel" || version.empty())
        throw ReadError(p + ": not CityGML: the root element is {" + std::string(uri) + "}" +
                        std::string(reader_local()) + ", expected a CityGML 1.0/2.0/3.0 CityModel");
      pending = scan();  // the header needs the first building when the file has no envelope
      make_header();
    } catch (...) {
      xmlFreeTextReader(rd);
      throw;
    }
  }
  ~Impl() { xmlFreeTextReader(rd); }

  std::string_view reader_local() const {
    const xmlChar* s = xmlTextReaderConstLocalName(rd);
    return s ? std::string_view(reinterpret_cast<const char*>(s)) : std::string_view();
  }
  std::string_view reader_uri() const {
    const xmlChar* s = xmlTextReaderConstNamespaceUri(rd);
    return s ? std::string_view(reinterpret_cast<const char*>(s)) : std::string_view();
  }

  int read(Move m) {
    const int r = m == Move::Skip ? xmlTextReaderNext(rd) : xmlTextReaderRead(rd);
    if (r < 0) fail();
    return r;
  }
  [[noreturn]] void fail() {
    throw ReadError(path +
                    ": malformed XML: " + (first_error.empty() ? std::string("unknown error") : first_error) +
                    " (after " + std::to_string(buildings) + " buildings)");
  }
  xmlNode* expand() {
    xmlNode* n = xmlTextReaderExpand(rd);
    if (!n) fail();
    return n;
  }

  // Advances to the next building and converts it; nullopt at the end of the document.
  std::optional<Feature> scan() {
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
        if (is_gml_ns(uri) && name == "boundedBy") {
          envelope(expand());
          next_move = Move::Skip;
        } else if (is_gml_ns(uri) && name == "name") {
          if (title.empty()) title = trim(text(expand()));
          next_move = Move::Skip;
        } else if (is_gml_ns(uri) && name != "featureMember") {
          next_move = Move::Skip;  // gml:description and other metadata of the model
        } else if (!(is_citygml_ns(uri) && name == "cityObjectMember") && !is_gml_ns(uri)) {
          ++skipped_top[std::string(name)];  // appearanceMember (global appearances), ...
          next_move = Move::Skip;
        }
        continue;  // a member: read on into it
      }
      next_move = Move::Skip;
      if (depth != 2) continue;
      if (!(is_citygml_ns(uri) && name == "Building")) {
        ++skipped[std::string(name)];
        continue;
      }
      ++buildings;
      citygml::ConvertedBuilding b =
          citygml::convert_building(expand(), "building-" + std::to_string(buildings));
      check_srs(b);
      return std::move(b.feature);
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

  void check_srs(const citygml::ConvertedBuilding& b) {
    if (!first_srs) first_srs = b.srs_name;
    if (!first_lower && !b.feature.vertices.empty()) {
      mc::Vec3 lo = b.feature.vertices[0];
      for (const auto& v : b.feature.vertices)
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      first_lower = lo;
    }
    if (!b.srs_name.empty() && !reference.empty() && citygml::reference_system(b.srs_name) != reference &&
        srs_mismatches++ == 0)
      srs_example = b.feature.id + " has srsName \"" + b.srs_name + "\"";
  }

  void make_header() {
    const std::string srs = !envelope_srs.empty() ? envelope_srs : first_srs.value_or("");
    reference = citygml::reference_system(srs);
    if (!srs.empty() && reference.empty())
      problems.push_back("srsName \"" + srs +
                         "\" is not an EPSG reference system; the output has no referenceSystem");
    // Millimetres from a whole-metre corner: the CityJSON quantisation the writer applies.
    const mc::Vec3 corner = lower ? *lower : first_lower.value_or(mc::Vec3{0, 0, 0});
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
    // Buildings converted before the header existed are checked against it now.
    if (pending && first_srs && !first_srs->empty() && !reference.empty() &&
        citygml::reference_system(*first_srs) != reference && srs_mismatches++ == 0)
      srs_example = pending->id + " has srsName \"" + *first_srs + "\"";
  }

  void finish() {
    auto list = [](const std::map<std::string, size_t>& m, size_t& total) {
      std::string s;
      total = 0;
      for (const auto& [name, n] : m) {
        s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + name;
        total += n;
      }
      return s;
    };
    size_t total = 0;
    if (!skipped.empty()) {
      const std::string s = list(skipped, total);
      problems.push_back("skipped " + std::to_string(total) + " city objects that are not buildings: " + s);
    }
    if (!skipped_top.empty()) {
      const std::string s = list(skipped_top, total);
      problems.push_back("not carried: " + std::to_string(total) + " top-level elements (" + s + ")");
    }
    if (srs_mismatches)
      problems.push_back(std::to_string(srs_mismatches) +
                         " buildings have an srsName other than the file's (" + srs_example +
                         "); coordinates are used as they are");
  }

  std::string path, first_error, version, title;
  xmlTextReaderPtr rd = nullptr;
  Move next_move = Move::Read;
  bool ended = false;
  size_t buildings = 0, srs_mismatches = 0;
  Header header;
  std::vector<std::string> problems;
  std::map<std::string, size_t> skipped, skipped_top;
  std::optional<Feature> pending;
  std::string envelope_srs, reference, srs_example;
  std::optional<std::string> first_srs;
  std::optional<mc::Vec3> lower, first_lower;
};

CityGmlReader::CityGmlReader(const std::string& path) : impl_(std::make_unique<Impl>(path)) {}
CityGmlReader::~CityGmlReader() = default;

const Header& CityGmlReader::header() const { return impl_->header; }
bool CityGmlReader::next(Feature& out) {
  if (impl_->pending) {
    out = std::move(*impl_->pending);
    impl_->pending.reset();
    return true;
  }
  auto f = impl_->scan();
  if (!f) return false;
  out = std::move(*f);
  return true;
}
const std::vector<std::string>& CityGmlReader::problems() const { return impl_->problems; }
std::string CityGmlReader::format() const { return "CityGML " + impl_->version; }
const std::map<std::string, size_t>& CityGmlReader::skipped_objects() const { return impl_->skipped; }

}  // namespace mc::io
