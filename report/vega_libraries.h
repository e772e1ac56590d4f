// The charting libraries the report inlines into its page: vega, vega-lite
// and vega-embed, the minified browser bundles scripts/fetch_vega puts in
// third_party/vega/. Inlined, not linked: the page must work offline and
// from file://, as one file to mail or archive beside the log.
#pragma once

#include <optional>
#include <string>

namespace alplan::report {

struct VegaLibraries {
  std::string vega;
  std::string vega_lite;
  std::string vega_embed;
};

struct VegaLibrariesResult {
  std::optional<VegaLibraries> libraries;
  std::string error;  // names the missing file and how to fetch it
};

// Reads DIR/vega.min.js, DIR/vega-lite.min.js and DIR/vega-embed.min.js.
VegaLibrariesResult load_vega_libraries(const std::string& dir);

// The text made safe inside an HTML <script> element: a "</script" in a
// string literal of the library would otherwise end the element early.
std::string script_safe(std::string javascript);

}  // namespace alplan::report
