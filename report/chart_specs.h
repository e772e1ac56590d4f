// The report's charts as Vega-Lite specifications, drawn in the browser by
// vega-embed. Declarative specs keep the C++ to data and encodings; the
// library does scales, axes, legends and tooltips. Each returns null when
// the log has nothing for that chart.
#pragma once

#include <nlohmann/json.hpp>

#include "report/event_log.h"
#include "report/plan_history.h"

namespace alplan::report {

// The Vega-Lite schema the specs are written for (vega-lite 6).
inline constexpr const char* kVegaLiteSchema = "https://vega.github.io/schema/vega-lite/v6.json";

// Plans over time, a row per robot and a sub-row per plan: steps coloured by
// plan, superseded steps that never ran in grey, failures and repairs marked.
nlohmann::json gantt_spec(const EventLog& log, const PlanHistory& history);

// The home from its room coordinates and connections, each robot's route
// (the moves it started) drawn over it.
nlohmann::json map_spec(const EventLog& log);

// Per senior: stress and emotion over time, goal windows, comforted and
// missed-window marks.
nlohmann::json timeline_spec(const EventLog& log);

// The last time the run's charts must show: its last event or goal window.
double run_end(const EventLog& log);

// Colours for categories, after Tableau 10 (Vega's default scheme), so plan
// colours in the legend read the same as elsewhere in Vega charts.
const char* category_colour(std::size_t i);

}  // namespace alplan::report
