#include "io/citygml_prescan.hpp"

#include <libxml/parser.h>

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

#include "io/citygml_input.hpp"
#include "io/citygml_xml.hpp"

namespace mc::io::citygml {

using namespace gmlxml;

namespace {

std::string_view sv(const xmlChar* s) { return s ? reinterpret_cast<const char*>(s) : std::string_view(); }

// The properties whose xlinks the building converter follows: every GML property (surfaceMember,
// exterior, baseSurface, ...) and CityGML's geometry, boundary-surface, opening and part
// properties. Others (appearance targets, addresses, ADEs) name nothing the converter reads.
bool followed(std::string_view uri, std::string_view name) {
  if (is_gml_ns(uri)) return true;
  if (!is_citygml_ns(uri)) return false;
  return name.rfind("lod", 0) == 0 || name == "boundedBy" || name == "boundary" || name == "opening" ||
         name == "fillingSurface" || name == "consistsOfBuildingPart" || name == "buildingPart";
}

// The SAX callbacks' state: the path down to the current element as depths, nothing else.
struct Pass {
  explicit Pass(Prescan& o) : out(o) {}
  Prescan& out;
  XmlInput* input = nullptr;
  int depth = 0;
  int skip_from = -1;  // the depth of a subtree that is skipped whole (not a member, not a Building)
  bool in_building = false;
  size_t text = 0;                 // of the current text node
  std::vector<uint64_t> ids;       // hashes of the gml:ids of the current Building
  std::vector<std::string> hrefs;  // its "#id" references, without '#'

  // One element inside a top-level Building: its gml:id, xlink:href and srsName.
  void element(std::string_view uri, std::string_view name, int n, const xmlChar** attributes) {
    for (int i = 0; i < n; ++i, attributes += 5) {
      const std::string_view local = sv(attributes[0]), ns = sv(attributes[2]);
      const std::string_view value(reinterpret_cast<const char*>(attributes[3]),
                                   static_cast<size_t>(attributes[4] - attributes[3]));
      if (local == "id" && is_gml_ns(ns)) {
        ids.push_back(std::hash<std::string_view>()(value));
      } else if (local == "href" && ns == kXlinkNs && followed(uri, name)) {
        if (value.size() > 1 && value[0] == '#') hrefs.emplace_back(value.substr(1));
      } else if (local == "srsName" && ns.empty() && out.first_srs.empty()) {
        out.first_srs = std::string(value);
      }
    }
  }

  // The building ends: its references to ids it does not define are remote. Ids are compared by
  // 64-bit hash, so that the pass copies no id that nothing refers to.
  void end_building() {
    if (!hrefs.empty()) {
      std::sort(ids.begin(), ids.end());
      for (auto& h : hrefs) {
        if (std::binary_search(ids.begin(), ids.end(), std::hash<std::string_view>()(h))) continue;
        if (out.remote_ids.count(h)) continue;
        if (out.remote_ids.size() < Prescan::kMaxRemoteIds &&
            out.remote_id_bytes + h.size() <= Prescan::kMaxRemoteIdBytes) {
          out.remote_id_bytes += h.size();
          out.remote_ids.insert(std::move(h));
        } else {
          ++out.remote_ids_dropped;
        }
      }
    }
    ids.clear();
    hrefs.clear();
  }

  static void start(void* ctx, const xmlChar* localname, const xmlChar*, const xmlChar* uri_, int,
                    const xmlChar**, int nb_attributes, int, const xmlChar** attributes) {
    Pass& p = *static_cast<Pass*>(ctx);
    const int d = p.depth++;
    p.text = 0;
    if (p.skip_from >= 0) return;
    const std::string_view name = sv(localname), uri = sv(uri_);
    if (d == 0) {
      if (name != "CityModel") p.input->stop();  // the main pass refuses it
    } else if (d == 1) {
      const Top t = top_level(uri, name);
      if (t != Top::Member && t != Top::UnqualifiedMember) p.skip_from = d;
    } else if (d == 2) {
      if (!(is_citygml_ns(uri) && name == "Building")) {
        p.skip_from = d;
        return;
      }
      ++p.out.buildings;
      p.in_building = true;
      p.element(uri, name, nb_attributes, attributes);
    } else {
      p.element(uri, name, nb_attributes, attributes);
    }
  }

  static void end(void* ctx, const xmlChar*, const xmlChar*, const xmlChar*) {
    Pass& p = *static_cast<Pass*>(ctx);
    const int d = --p.depth;
    p.text = 0;
    if (p.skip_from == d) p.skip_from = -1;
    if (p.in_building && d == 2) {
      p.end_building();
      p.in_building = false;
    }
  }

  // Text is not looked at, only measured: libxml2's limit of 10,000,000 bytes per text node is
  // enforced where a tree is built, which this pass does not do.
  static void characters(void* ctx, const xmlChar*, int len) {
    Pass& p = *static_cast<Pass*>(ctx);
    p.text += static_cast<size_t>(len);
    if (p.text > 10'000'000) p.input->stop();
  }
};

}  // namespace

Prescan prescan(const std::string& path) {
  Prescan out;
  Pass pass(out);
  xmlSAXHandler callbacks{};
  callbacks.startElementNs = &Pass::start;
  callbacks.endElementNs = &Pass::end;
  callbacks.characters = &Pass::characters;
  callbacks.cdataBlock = &Pass::characters;
  XmlInput in(path, callbacks, &pass);
  pass.input = &in;
  out.complete = in.parse();
  return out;
}

}  // namespace mc::io::citygml
