#include "io/citygml_remote.hpp"

#include "io/citygml_input.hpp"
#include "io/citygml_xml.hpp"

namespace mc::io::citygml {

using namespace gmlxml;

namespace {

// What a stored node costs beside its text: libxml2's struct, its copied name, attribute or
// namespace and the allocator's share (measured: 20,000 stored polygons of 5 nodes take 29 MB).
constexpr size_t kNodeBytes = 250;

}  // namespace

RemoteGeometry::RemoteGeometry() {
  doc_ = xmlNewDoc(reinterpret_cast<const xmlChar*>("1.0"));
  root_ = xmlNewNode(nullptr, reinterpret_cast<const xmlChar*>("store"));
  xmlDocSetRootElement(doc_, root_);
}

RemoteGeometry::~RemoteGeometry() { xmlFreeDoc(doc_); }

const xmlNode* RemoteGeometry::find(const std::string& id) const {
  auto it = by_id_.find(id);
  return it == by_id_.end() ? nullptr : it->second;
}

std::vector<std::string> RemoteGeometry::problems() const {
  if (dropped_.empty()) return {};
  return {"the store of xlink targets outside their building is full (" + std::to_string(bytes_ >> 20) +
          " MB, " + std::to_string(stored_) + " elements): " + std::to_string(dropped_.size()) +
          " more are not stored, and the surfaces that refer to them are missing"};
}

void RemoteGeometry::collect(const std::string& path, std::unordered_set<std::string> ids, size_t max_bytes) {
  Ids wanted(ids.begin(), ids.end());
  for (int n = 0; n < kMaxPasses && !wanted.empty(); ++n) {
    Ids later;  // named by stored elements: perhaps before them in the file, so another pass
    pass(path, wanted, later, max_bytes);
    wanted.clear();
    for (const auto& id : later)
      if (!by_id_.count(id) && !dropped_.count(id)) wanted.insert(id);
  }
}

void RemoteGeometry::pass(const std::string& path, Ids& wanted, Ids& later, size_t max_bytes) {
  XmlInput in(path);
  xmlTextReaderPtr rd = in.reader();
  std::vector<std::string> dimension;  // srsDimension in force at each depth (GML inherits it)
  bool skip = false;
  while ((skip ? xmlTextReaderNext(rd) : xmlTextReaderRead(rd)) == 1) {
    skip = false;
    if (xmlTextReaderNodeType(rd) != XML_READER_TYPE_ELEMENT) continue;
    const size_t depth = static_cast<size_t>(xmlTextReaderDepth(rd));
    xmlNode* n = xmlTextReaderCurrentNode(rd);
    dimension.resize(depth + 1);
    const std::string own = attr(n, "srsDimension");
    dimension[depth] = !own.empty() ? own : depth ? dimension[depth - 1] : std::string();
    if (!n->properties || !is_gml_ns(ns_uri(n))) continue;
    const std::string id = gml_id(n);
    if (id.empty() || !wanted.count(id) || by_id_.count(id)) continue;
    if (full_) {
      dropped_.insert(id);
      continue;
    }
    xmlNode* subtree = xmlTextReaderExpand(rd);
    if (!subtree) break;
    store(subtree, depth ? dimension[depth - 1] : std::string(), wanted, later, max_bytes);
    skip = true;
  }
}

void RemoteGeometry::store(xmlNode* original, const std::string& inherited_dimension, Ids& wanted, Ids& later,
                           size_t max_bytes) {
  xmlNode* copy = xmlDocCopyNode(original, doc_, 1);
  if (!copy) return;
  // Its size, its ids, and the xlinks it makes to elements outside itself.
  size_t bytes = 0;
  std::vector<std::pair<std::string, const xmlNode*>> ids;
  std::vector<std::string> refs;
  std::vector<const xmlNode*> stack{copy};
  while (!stack.empty()) {
    const xmlNode* n = stack.back();
    stack.pop_back();
    bytes += kNodeBytes;
    if (n->type == XML_TEXT_NODE && n->content) bytes += xmlStrlen(n->content);
    if (n->type != XML_ELEMENT_NODE) continue;
    if (std::string id = gml_id(n); !id.empty()) ids.emplace_back(std::move(id), n);
    if (const std::string h = href(n); h.size() > 1 && h[0] == '#') refs.push_back(h.substr(1));
    for (const xmlNode* c = n->children; c; c = c->next) stack.push_back(c);
  }
  if (bytes_ + bytes > max_bytes) {
    xmlFreeNode(copy);
    dropped_.insert(gml_id(original));
    full_ = true;  // what comes later is not even expanded
    return;
  }
  // Coordinates below it read with the dimension of the original's ancestors.
  if (!inherited_dimension.empty() && attr(copy, "srsDimension").empty())
    xmlSetProp(copy, reinterpret_cast<const xmlChar*>("srsDimension"),
               reinterpret_cast<const xmlChar*>(inherited_dimension.c_str()));
  xmlAddChild(root_, copy);
  bytes_ += bytes;
  ++stored_;
  for (auto& [id, node] : ids) by_id_.emplace(std::move(id), node);
  for (auto& r : refs)
    if (!by_id_.count(r) && !dropped_.count(r) && wanted.insert(r).second) later.insert(std::move(r));
}

}  // namespace mc::io::citygml
