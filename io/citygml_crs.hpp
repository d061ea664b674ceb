// CityGML srsName -> the OGC URL CityJSON's metadata.referenceSystem uses.
#pragma once
#include <string>

namespace mc::io::citygml {

// "EPSG:28992", "urn:ogc:def:crs:EPSG::28992", "http://www.opengis.net/def/crs/EPSG/0/28992",
// compound URNs ("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837": the horizontal part), and the
// German AdV names ("urn:adv:crs:ETRS89_UTM32*DHHN92" -> 5555) become
// "https://www.opengis.net/def/crs/EPSG/0/<code>"; empty when not understood.
std::string reference_system(const std::string& srs_name);

}  // namespace mc::io::citygml
