// The HTML report's page template, stylesheet and script (report/html/) and the three.js bundle
// (tools/html/setup.sh), embedded at build time by report/html/assets.cmake.
#pragma once

namespace mc::report::html_assets {

extern const char kPageHtml[];  // the page with @TITLE@ @CSS@ @DATA@ @THREE@ @JS@ placeholders
extern const char kPageCss[];
extern const char kPageJs[];
extern const char kThreeJs[];  // empty when the build had no bundle
extern const bool kHasThree;

}  // namespace mc::report::html_assets
