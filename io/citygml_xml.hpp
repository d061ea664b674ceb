// Small libxml2 helpers of the CityGML reader. Elements are recognised by namespace URI and local
// name, never by prefix, so `gml:`, `bldg:` or a default namespace all read the same.
#pragma once
#include <libxml/tree.h>

#include <string>
#include <string_view>

namespace mc::io::gmlxml {

inline std::string_view local(const xmlNode* n) {
  return n && n->name ? std::string_view(reinterpret_cast<const char*>(n->name)) : std::string_view();
}
inline std::string_view ns_uri(const xmlNode* n) {
  return n && n->ns && n->ns->href ? std::string_view(reinterpret_cast<const char*>(n->ns->href))
                                   : std::string_view();
}
inline bool is_element(const xmlNode* n) { return n && n->type == XML_ELEMENT_NODE; }

// GML 3.1.1 (CityGML 1.0/2.0) or GML 3.2 (CityGML 3.0).
inline bool is_gml_ns(std::string_view uri) {
  return uri == "http://www.opengis.net/gml" || uri == "http://www.opengis.net/gml/3.2";
}
// Any CityGML module namespace (core, building, construction, generics, ...) of any version.
inline bool is_citygml_ns(std::string_view uri) {
  return uri.rfind("http://www.opengis.net/citygml/", 0) == 0;
}
inline bool is_generics_ns(std::string_view uri) {
  return is_citygml_ns(uri) && uri.find("/generics/") != std::string_view::npos;
}
inline constexpr std::string_view kXlinkNs = "http://www.w3.org/1999/xlink";
// "1.0", "2.0" or "3.0" for a CityGML namespace of that version (core ".../citygml/2.0" or a module
// ".../citygml/building/2.0"); empty for anything else.
inline std::string_view citygml_version(std::string_view uri) {
  if (!is_citygml_ns(uri) || uri.size() < 4) return {};
  const std::string_view v = uri.substr(uri.size() - 4);
  return v == "/1.0" || v == "/2.0" || v == "/3.0" ? v.substr(1) : std::string_view();
}
// The CityGML core namespace (where CityModel and cityObjectMember live) of a version.
inline bool is_core_ns(std::string_view uri) {
  return is_citygml_ns(uri) && !citygml_version(uri).empty() &&
         uri.size() == std::string_view("http://www.opengis.net/citygml/2.0").size();
}
// An Application Domain Extension (PLATEAU's uro:, ...) or any other foreign namespace: not GML,
// CityGML or XLink. Elements without a namespace are not in one.
inline bool is_ade_ns(std::string_view uri) {
  return !uri.empty() && !is_gml_ns(uri) && !is_citygml_ns(uri) && uri != kXlinkNs;
}

// What a child of the CityModel is. Some exporters declare no default namespace, which leaves the
// root and its direct children unqualified: those members and the envelope are read all the same
// (the reader warns), anything else unqualified is "Other".
enum class Top { Member, UnqualifiedMember, Envelope, UnqualifiedEnvelope, Name, Metadata, Ade, Other };
inline Top top_level(std::string_view uri, std::string_view name) {
  const bool member = name == "cityObjectMember" || name == "featureMember" || name == "featureMembers";
  if (is_gml_ns(uri)) {
    if (name == "featureMember" || name == "featureMembers") return Top::Member;
    if (name == "boundedBy") return Top::Envelope;
    return name == "name" ? Top::Name : Top::Metadata;  // gml:description and other metadata
  }
  if (is_citygml_ns(uri)) return name == "cityObjectMember" ? Top::Member : Top::Other;
  if (uri.empty())
    return member ? Top::UnqualifiedMember : name == "boundedBy" ? Top::UnqualifiedEnvelope : Top::Other;
  return is_ade_ns(uri) ? Top::Ade : Top::Other;
}

inline bool gml(const xmlNode* n, std::string_view name) {
  return is_element(n) && local(n) == name && is_gml_ns(ns_uri(n));
}

// Element children in document order: for (auto* c = first_child(n); c; c = next_sibling(c)).
inline xmlNode* next_sibling(const xmlNode* n) {
  for (xmlNode* s = n ? n->next : nullptr; s; s = s->next)
    if (is_element(s)) return s;
  return nullptr;
}
inline xmlNode* first_child(const xmlNode* n) {
  for (xmlNode* c = n ? n->children : nullptr; c; c = c->next)
    if (is_element(c)) return c;
  return nullptr;
}

// An attribute without namespace ("srsName") or in one namespace; empty when absent.
inline std::string attr(const xmlNode* n, const char* name, const char* ns = nullptr) {
  xmlChar* v =
      ns ? xmlGetNsProp(n, reinterpret_cast<const xmlChar*>(name), reinterpret_cast<const xmlChar*>(ns))
         : xmlGetNoNsProp(n, reinterpret_cast<const xmlChar*>(name));
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}
inline std::string gml_id(const xmlNode* n) {
  std::string id = attr(n, "id", "http://www.opengis.net/gml");
  return id.empty() ? attr(n, "id", "http://www.opengis.net/gml/3.2") : id;
}
inline std::string href(const xmlNode* n) { return attr(n, "href", kXlinkNs.data()); }

// "uro:buildingDetailAttribute": an element as the file names it (with its prefix, if any).
inline std::string qualified_name(const xmlNode* n) {
  std::string name(local(n));
  if (n && n->ns && n->ns->prefix) name = reinterpret_cast<const char*>(n->ns->prefix) + (":" + name);
  return name;
}

// The text content of an element (all descendant text).
inline std::string text(const xmlNode* n) {
  xmlChar* v = xmlNodeGetContent(n);
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

inline std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

}  // namespace mc::io::gmlxml
