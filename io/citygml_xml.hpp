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
inline std::string href(const xmlNode* n) { return attr(n, "href", "http://www.w3.org/1999/xlink"); }

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
