// The report as one self-contained HTML page: the summary and explanations
// as plain HTML, the charts as Vega-Lite specs drawn in the browser by the
// inlined libraries (vega_libraries.h). Everything from the log is escaped.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "report/event_log.h"
#include "report/vega_libraries.h"

namespace alplan::report {

std::string render_report_page(const EventLog& log, const std::string& log_name, const VegaLibraries& libraries);

// Text for HTML element content and attribute values.
std::string html_escape(const std::string& text);

// JSON to embed in a <script> element: every '<' written as \u003c, which
// JSON allows inside strings, the only place a '<' can be.
std::string script_json(const nlohmann::json& j);

}  // namespace alplan::report
