#include "report/vega_libraries.h"

#include <cctype>
#include <fstream>
#include <sstream>

namespace alplan::report {
namespace {

bool read_whole(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return !text.empty();
}

}  // namespace

VegaLibrariesResult load_vega_libraries(const std::string& dir) {
  VegaLibraries libs;
  const std::pair<const char*, std::string*> files[] = {
      {"vega.min.js", &libs.vega}, {"vega-lite.min.js", &libs.vega_lite}, {"vega-embed.min.js", &libs.vega_embed}};
  for (const auto& [name, text] : files) {
    const std::string path = dir + "/" + name;
    if (!read_whole(path, *text)) {
      return {std::nullopt, path + ": error: cannot read the charting library the report inlines; "
                                   "run scripts/setup (or scripts/fetch_vega) to fetch it, or give --vega-dir"};
    }
  }
  return {std::move(libs), ""};
}

std::string script_safe(std::string javascript) {
  // "<\/script" means the same inside a JavaScript string or regular
  // expression, the only places valid code can hold it.
  for (std::size_t at = javascript.find("</"); at != std::string::npos; at = javascript.find("</", at + 2)) {
    const std::string next = javascript.substr(at + 2, 6);
    std::string lower;
    for (char c : next) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "script") javascript.replace(at, 2, "<\\/");
  }
  return javascript;
}

}  // namespace alplan::report
