// One CityGML Building (an expanded XML subtree, any CityGML version) as a CityJSON 2.0 Feature:
// the Building and its BuildingParts as CityObjects with attributes and semantic geometry.
#pragma once
#include <libxml/tree.h>

#include <string>

#include "io/citygml_ade.hpp"
#include "io/cityjson_types.hpp"

namespace mc::io::citygml {

class RemoteGeometry;

struct ConvertedBuilding {
  Feature feature;
  std::string srs_name;                // the first srsName inside the building (empty if none)
  std::vector<std::string> srs_names;  // every distinct one (on the building or its geometry)
  AdeTally ade;                        // ADE elements of the building, its parts and surfaces
};

// `fallback_id` names the building when it has no gml:id. Never throws on bad data: problems go
// to feature.problems; coordinates that cannot be read (2D, broken) leave the building without
// geometry and the reason first in feature.problems (the pipeline then skips it with that reason).
// `remote` (may be null) resolves xlinks to geometry outside the building.
ConvertedBuilding convert_building(const xmlNode* building, const std::string& fallback_id,
                                   const RemoteGeometry* remote = nullptr);

}  // namespace mc::io::citygml
