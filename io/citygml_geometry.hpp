// GML geometry of one CityGML building (an expanded XML subtree) into indexed polygons.
// xlink:href="#id" references are resolved inside the building, else among the geometry copied
// from elsewhere in the file (RemoteGeometry); coordinates are pooled so that equal points share
// one vertex.
#pragma once
#include <libxml/tree.h>

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/vec3.hpp"

namespace mc::io::citygml {

class RemoteGeometry;

struct Polygon {
  std::vector<std::vector<uint32_t>> rings;  // exterior first, no repeated closing point
  const xmlNode* source = nullptr;           // the defining element: the same surface reached via
                                             // two xlinks has one source (semantics, de-duplication)
};

struct Solid {
  std::vector<std::vector<Polygon>> shells;  // exterior shell first
};

struct Geometry {
  std::string type;  // CityJSON type: MultiSurface, CompositeSurface, Solid, CompositeSolid, MultiSolid
  std::vector<Polygon> surfaces;  // the surface types
  std::vector<Solid> solids;      // the solid types (one for Solid)
  bool is_solid() const { return !solids.empty(); }
};

class GeometryReader {
 public:
  // Indexes every gml:id below `building` (the first scope of xlinks) and notes its srsNames.
  // `remote` (may be null) resolves xlinks to geometry outside the building.
  explicit GeometryReader(const xmlNode* building, const RemoteGeometry* remote = nullptr);

  // The content of a geometry property (lod2Solid, lod2MultiSurface, ...), following xlink:href.
  // nullopt when it holds nothing usable (the reason is in notes() or fatal()).
  std::optional<Geometry> read(const xmlNode* property);
  // Every polygon below a surface property, flattened (boundary surfaces).
  std::vector<Polygon> read_surfaces(const xmlNode* property);
  // The element a property stands for: its child, or the target of its xlink:href (null if absent).
  const xmlNode* content(const xmlNode* property);

  std::vector<mc::Vec3>& vertices() { return vertices_; }
  // The first error that makes the building's geometry unusable (2D or broken coordinates).
  const std::string& fatal() const { return fatal_; }
  std::vector<std::string>& notes() { return notes_; }
  const std::string& srs_name() const { return srs_name_; }
  // The distinct srsNames on the building and its geometry, in document order (at most 8).
  const std::vector<std::string>& srs_names() const { return srs_names_; }

 private:
  void surfaces(const xmlNode* el, bool flip, std::vector<Polygon>& out, int depth);
  void member_surfaces(const xmlNode* member, bool flip, std::vector<Polygon>& out, int depth);
  std::optional<Solid> solid(const xmlNode* el, int depth);
  void solids(const xmlNode* el, std::vector<Solid>& out, int depth);
  std::optional<Polygon> polygon(const xmlNode* el, bool flip);
  std::vector<uint32_t> ring(const xmlNode* el);
  bool coordinates(const xmlNode* el, std::vector<double>& xyz);
  int dimension(const xmlNode* el) const;
  uint32_t vertex(double x, double y, double z);
  void note(std::string msg);
  void fail(std::string msg);

  struct Key {
    double x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };

  const xmlNode* root_;
  const RemoteGeometry* remote_;
  std::unordered_map<std::string, const xmlNode*> by_id_;
  std::unordered_map<Key, uint32_t, KeyHash> pool_;
  std::vector<mc::Vec3> vertices_;
  std::string fatal_, srs_name_;
  std::vector<std::string> notes_, srs_names_;
};

}  // namespace mc::io::citygml
