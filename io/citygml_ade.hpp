// Tally of skipped Application Domain Extension elements (PLATEAU's uro:, any foreign namespace):
// they are not read, and the file's problems say how many of which were left out.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace mc::io::citygml {

struct AdeTally {
  std::map<std::string, size_t> elements;         // "uro:buildingDetailAttribute" -> count
  std::map<std::string, std::string> namespaces;  // "uro" -> its namespace URI (first seen)

  void add(std::string qualified_name, std::string_view uri) {
    const auto colon = qualified_name.find(':');
    namespaces.try_emplace(colon == std::string::npos ? std::string() : qualified_name.substr(0, colon),
                           std::string(uri));
    ++elements[std::move(qualified_name)];
  }
  void merge(const AdeTally& o) {
    for (const auto& [name, n] : o.elements) elements[name] += n;
    for (const auto& [prefix, uri] : o.namespaces) namespaces.try_emplace(prefix, uri);
  }
  bool empty() const { return elements.empty(); }

  // "skipped 14 ADE elements: 12 uro:buildingDetailAttribute, 2 uro:buildingIDAttribute
  // (uro = https://www.geospatial.jp/iur/uro/2.0)"; the 20 most frequent kinds are named.
  std::string summary() const {
    constexpr size_t kNamed = 20;
    std::multimap<size_t, const std::string*, std::greater<>> by_count;
    size_t total = 0;
    for (const auto& [name, n] : elements) {
      by_count.emplace(n, &name);
      total += n;
    }
    std::string s = "skipped " + std::to_string(total) + " ADE elements: ";
    size_t listed = 0;
    for (const auto& [n, name] : by_count) {
      if (listed == kNamed) {
        s += ", and " + std::to_string(by_count.size() - kNamed) + " other kinds";
        break;
      }
      s += (listed++ ? ", " : "") + std::to_string(n) + " " + *name;
    }
    std::string ns;
    for (const auto& [prefix, uri] : namespaces)
      ns += (ns.empty() ? "" : ", ") + (prefix.empty() ? std::string("(no prefix)") : prefix) + " = " + uri;
    return s + " (" + ns + ")";
  }
};

}  // namespace mc::io::citygml
