// The HTML report's page template, stylesheet and script (pipeline/html/) and the three.js bundle
// (tools/html/setup.sh), embedded at build time by pipeline/html/assets.cmake.
#pragma once

namespace mc::pipeline::html_assets {

extern const char kPageHtml[];  // the page with @TITLE@ @CSS@ @DATA@ @THREE@ @JS@ placeholders
extern const char kPageCss[];
extern const char kPageJs[];
extern const char kThreeJs[];  // empty when the build had no bundle
extern const bool kHasThree;

}  // namespace mc::pipeline::html_assets
