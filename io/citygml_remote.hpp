// GML geometry named by xlinks from outside its top-level Building (a wall shared by two
// buildings, a building's surfaces defined once under another feature). The main pass holds one
// building at a time, so an extra pass copies these elements out of the file into a private
// document beforehand. The store is bounded (about kMaxBytes); targets beyond it stay unresolved
// and are reported.
#pragma once
#include <libxml/tree.h>

#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace mc::io::citygml {

class RemoteGeometry {
 public:
  // Text plus 250 bytes per node, near what the copies take: 64 MB hold some 50,000 small
  // polygons, or about 2 million coordinates in large ones.
  static constexpr size_t kMaxBytes = size_t(64) << 20;

  RemoteGeometry();
  ~RemoteGeometry();
  RemoteGeometry(const RemoteGeometry&) = delete;
  RemoteGeometry& operator=(const RemoteGeometry&) = delete;

  // Reads `path` and copies every GML element whose gml:id is in `ids`, with what it refers to in
  // turn (another pass when that lies before it in the file; at most kMaxPasses). An XML error
  // ends a pass quietly: the main pass reports it where it meets it. Throws ReadError only when
  // the file cannot be opened.
  void collect(const std::string& path, std::unordered_set<std::string> ids, size_t max_bytes = kMaxBytes);

  // The stored element with this gml:id (any id inside a stored element too), or null.
  const xmlNode* find(const std::string& id) const;
  // Whether the element exists but was not stored because the store was full.
  bool dropped(const std::string& id) const { return dropped_.count(id) > 0; }
  size_t elements() const { return stored_; }
  size_t bytes() const { return bytes_; }
  // "the store of xlink targets outside their building is full ..." (empty when it is not).
  std::vector<std::string> problems() const;

  static constexpr int kMaxPasses = 3;

 private:
  struct Hash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>()(s); }
  };
  using Ids = std::unordered_set<std::string, Hash, std::equal_to<>>;
  void pass(const std::string& path, Ids& wanted, Ids& later, size_t max_bytes);
  void store(xmlNode* original, const std::string& inherited_dimension, Ids& wanted, Ids& later,
             size_t max_bytes);

  xmlDocPtr doc_ = nullptr;
  xmlNodePtr root_ = nullptr;
  std::unordered_map<std::string, const xmlNode*> by_id_;
  std::unordered_set<std::string> dropped_;
  size_t stored_ = 0, bytes_ = 0;
  bool full_ = false;
};

}  // namespace mc::io::citygml
