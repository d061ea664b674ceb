#include "io/citygml_crs.hpp"

#include <regex>

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
  std::smatch m;
  // The first EPSG code: for compound URNs the horizontal CRS (a compound EPSG code for the pair
  // cannot be derived from the two codes).
  static const std::regex epsg(R"(EPSG(?:/[^/]*/|:[^:,]*:|:)(\d+))", std::regex::icase);
  if (std::regex_search(srs_name, m, epsg))
    code = m[1].str();
  else if (srs_name.find("adv:crs:") != std::string::npos || srs_name.find("ADV:CRS:") != std::string::npos)
    code = adv_code(srs_name);
  return code.empty() ? "" : "https://www.opengis.net/def/crs/EPSG/0/" + code;
}

}  // namespace mc::io::citygml
