#include "io/citygml_crs.hpp"

#include <regex>

#include "io/crs.hpp"

namespace mc::io::citygml {

namespace {

// AdV (German survey) CRS names: ETRS89 / UTM 31-33 with DHHN92 heights have compound EPSG codes;
// other heights (DHHN2016, none) keep the horizontal code. Gauss-Krueger zones 2-5 on DHDN.
std::string adv_code(const std::string& name) {
  static const std::regex utm(R"(ETRS89_UTM(3[123])(\*(\w+))?)", std::regex::icase);
  static const std::regex gk(R"(DE_DHDN_3GK([2-5]))", std::regex::icase);
  std::smatch m;
  if (std::regex_search(name, m, utm)) {
    const int zone = std::stoi(m[1].str());
    if (m[3].matched && m[3].str() == "DHHN92") return std::to_string(5554 + zone - 31);
    return std::to_string(25800 + zone);
  }
  if (std::regex_search(name, m, gk)) return std::to_string(31464 + std::stoi(m[1].str()));
  return "";
}

}  // namespace

std::string reference_system(const std::string& srs_name) {
  std::string code;
  if (srs_name.find("adv:crs:") != std::string::npos || srs_name.find("ADV:CRS:") != std::string::npos) {
    code = adv_code(srs_name);
  } else {
    // A compound URN ("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837") by its horizontal part: a
    // compound EPSG code cannot be derived from the two codes.
    std::string single = srs_name;
    if (const auto at = srs_name.find(",crs:"); at != std::string::npos) {
      const auto end = srs_name.find(',', at + 1);
      single = "urn:ogc:def:crs:" + srs_name.substr(at + 5, end == std::string::npos ? end : end - at - 5);
    }
    const std::string epsg = normalize_crs(single);  // "EPSG:<code>" for the OGC spellings
    if (epsg.rfind("EPSG:", 0) == 0) code = epsg.substr(5);
  }
  return code.empty() ? "" : "https://www.opengis.net/def/crs/EPSG/0/" + code;
}

}  // namespace mc::io::citygml
