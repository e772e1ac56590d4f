#include "report/html_page.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/chart_specs.h"
#include "report/plan_history.h"
#include "report/summary.h"

namespace alplan::report {
namespace {

using nlohmann::json;

std::string number(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  std::string s = buffer;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em 2em; color: #222; max-width: 1300px; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; } h2 { font-size: 1.2em; margin-top: 1.6em; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; margin: 0.5em 0; } td, th { border: 1px solid #ccc; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
.caption { color: #555; margin: 0.2em 0 0.6em; } .chart { min-height: 40px; }
.error { color: #b00; font-weight: bold; } .meta { color: #555; }
)";

// Chart ids and the script that draws them; a chart vega-embed refuses
// shows its error in its place, so a broken spec is seen, not a blank.
constexpr const char* kDrawCharts = R"(
for (const [id, spec] of Object.entries(alplanSpecs)) {
  if (!spec) continue;
  vegaEmbed('#' + id, spec, {renderer: 'svg', actions: false}).catch(function (err) {
    const p = document.createElement('p');
    p.className = 'error';
    p.textContent = 'Chart not drawn: ' + err.message;
    document.getElementById(id).replaceChildren(p);
  });
}
document.getElementById('versions').textContent =
  'Charts: Vega-Lite specs drawn by vega ' + vega.version + ', vega-lite ' + vegaLite.version +
  ' and vega-embed ' + vegaEmbed.version + ', inlined in this page.';
)";

// Each robot's busy share, in all and hour by hour.
void utilisation_table(std::ostream& out, const RunSummary& s) {
  out << "<table id=\"utilisation\">\n<tr><th>robot</th><th>busy (s)</th><th>busy share</th>"
         "<th>busy share per hour of the run</th></tr>\n";
  for (const RobotUtilisation& u : s.robots) {
    std::string hours;
    for (double share : u.busy_share_per_hour) {
      hours += (hours.empty() ? "" : " ") + std::to_string(static_cast<int>(std::lround(100.0 * share))) + "%";
    }
    const double share = s.end_time > 0 ? u.busy_seconds / s.end_time : 0.0;
    out << "<tr><td>" << html_escape(u.robot) << "</td><td class=\"n\">" << number(u.busy_seconds)
        << "</td><td class=\"n\">" << std::lround(100.0 * share) << "%</td><td>" << hours << "</td></tr>\n";
  }
  if (s.robots.empty()) out << "<tr><td colspan=\"4\">no robot acted in the log</td></tr>\n";
  out << "</table>\n";
}

void row(std::ostream& out, const std::string& name, double value) {
  out << "<tr><th>" << html_escape(name) << "</th><td class=\"n\">" << number(value) << "</td></tr>\n";
}

void summary_section(std::ostream& out, const RunSummary& s) {
  out << "<h2>Summary</h2>\n<table id=\"summary\">\n";
  row(out, "seniors with goals", s.seniors_with_goals);
  row(out, "goals", s.goals);
  row(out, "comforted", s.comforted);
  row(out, "comforted within the window", s.within_window);
  row(out, "windows missed", s.windows_missed);
  row(out, "failures", s.failures);
  row(out, "foreseen failures", s.foreseen_failures);
  row(out, "plans", s.plans);
  row(out, "explanations", s.explanations);
  row(out, "last event at (s)", s.end_time);
  out << "</table>\n<table id=\"seniors\">\n<tr><th>senior</th><th>goals</th><th>comforted</th>"
         "<th>within window</th><th>late</th><th>mean lateness (s)</th><th>worst lateness (s)</th>"
         "<th>windows missed</th></tr>\n";
  for (const SeniorSummary& p : s.seniors) {
    out << "<tr><td>" << html_escape(p.senior) << "</td><td class=\"n\">" << p.goals << "</td><td class=\"n\">"
        << p.comforted << "</td><td class=\"n\">" << p.within_window << "</td><td class=\"n\">" << p.late
        << "</td><td class=\"n\">" << (p.late ? number(p.lateness_total / p.late) : std::string("-"))
        << "</td><td class=\"n\">" << (p.late ? number(p.lateness_max) : std::string("-")) << "</td><td class=\"n\">"
        << p.windows_missed << "</td></tr>\n";
  }
  out << "</table>\n";
  utilisation_table(out, s);
  out << "<table id=\"repairs\">\n<tr><th>repair strategy</th><th>attempts</th><th>repaired</th>"
         "<th>seconds</th></tr>\n";
  for (const StrategySummary& r : s.repairs) {
    out << "<tr><td>" << html_escape(r.strategy) << "</td><td class=\"n\">" << r.attempts << "</td><td class=\"n\">"
        << r.repaired << "</td><td class=\"n\">" << number(r.seconds) << "</td></tr>\n";
  }
  if (s.repairs.empty()) out << "<tr><td colspan=\"4\">no repair in the log</td></tr>\n";
  out << "</table>\n";
  if (s.batteries.empty()) return;  // a run without batteries
  out << "<table id=\"batteries\">\n<tr><th>robot</th><th>lowest battery</th><th>reserve</th>"
         "<th>below its reserve</th></tr>\n";
  for (const BatterySummary& b : s.batteries) {
    out << "<tr><td>" << html_escape(b.robot) << "</td><td class=\"n\">" << number(b.lowest) << "</td><td class=\"n\">"
        << number(b.reserve) << "</td><td>" << (b.below_reserve ? "yes" : "no") << "</td></tr>\n";
  }
  out << "</table>\n";
}

void explanations_section(std::ostream& out, const EventLog& log) {
  out << "<h2>Explanations</h2>\n<table id=\"explanations\">\n"
         "<tr><th>time (s)</th><th>senior</th><th>why</th><th>what</th><th>how</th></tr>\n";
  int n = 0;
  for (const Event& e : log.events) {
    if (e.type != "explanation") continue;
    ++n;
    out << "<tr><td class=\"n\">" << number(e.time) << "</td><td>" << html_escape(e.senior.empty() ? "-" : e.senior)
        << "</td>";
    for (const char* part : {"why", "what", "how"}) out << "<td>" << html_escape(text_field(e.fields, part, "-")) << "</td>";
    out << "</tr>\n";
  }
  if (n == 0) out << "<tr><td colspan=\"5\">no explanation in the log</td></tr>\n";
  out << "</table>\n";
}

void chart_section(std::ostream& out, const char* id, const char* title, const char* caption, const json& spec,
                   const char* empty) {
  out << "<h2>" << title << "</h2>\n<p class=\"caption\">" << caption << "</p>\n<div id=\"" << id
      << "\" class=\"chart\">";
  if (spec.is_null()) out << "<p class=\"meta\">" << empty << "</p>";
  out << "</div>\n";
}

// A setting as a person reads it: text as it is, a list one item after
// another, an object as "key value" pairs; never a JSON blob.
std::string readable(const json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number()) return number(value.get<double>());
  if (value.is_null()) return "-";
  std::string out;
  if (value.is_array()) {
    for (const json& item : value) out += (out.empty() ? "" : "; ") + readable(item);
    return out.empty() ? "(none)" : out;
  }
  for (const auto& [key, item] : value.items()) out += (out.empty() ? "" : ", ") + key + " " + readable(item);
  return out.empty() ? "(none)" : out;
}

void settings_line(std::ostream& out, const EventLog& log, const std::string& log_name) {
  out << "<p class=\"meta\">From <code>" << html_escape(log_name) << "</code></p>\n";
  if (!log.settings.is_object()) return;
  out << "<details><summary>Settings of the run</summary>\n<table id=\"settings\">\n";
  for (const auto& [key, value] : log.settings.items()) {
    out << "<tr><th>" << html_escape(key) << "</th><td>" << html_escape(readable(value)) << "</td></tr>\n";
  }
  out << "</table></details>\n";
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string script_json(const json& j) {
  // Invalid UTF-8 from the log is replaced rather than thrown on.
  const std::string text = j.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

std::string render_report_page(const EventLog& log, const std::string& log_name, const VegaLibraries& libraries) {
  const PlanHistory history = plan_history(log);
  const json specs = {{"gantt", gantt_spec(log, history)}, {"map", map_spec(log)}, {"timeline", timeline_spec(log)}};
  const std::string home = log.home && !log.home->name.empty() ? log.home->name : "(unnamed home)";
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>alplan report: "
      << html_escape(home) << "</title>\n<style>" << kStyle << "</style>\n";
  for (const std::string* lib : {&libraries.vega, &libraries.vega_lite, &libraries.vega_embed}) {
    out << "<script>" << script_safe(*lib) << "</script>\n";
  }
  out << "</head>\n<body>\n<h1>Run report: " << html_escape(home) << "</h1>\n";
  settings_line(out, log, log_name);
  summary_section(out, summarize(log));
  chart_section(out, "gantt", "Plans over time",
                "A row per robot, a sub-row per plan; steps coloured by plan, grey where a later plan superseded them "
                "before they started. Red crosses: failures. Dashed lines: repairs (green repaired, orange not).",
                specs["gantt"], "No plan in the log.");
  chart_section(out, "map", "The home and the robots' routes",
                "Rooms at their coordinates, connections in grey, each robot's route through the moves it started.",
                specs["map"], "No home with room coordinates in the log.");
  chart_section(out, "timeline", "Stress, emotion and goals per senior",
                "Stress score (big dots: stressed) and recognised emotions; goal windows shaded from the goal to its "
                "window end; comforted (in time or late) and missed windows as vertical lines.",
                specs["timeline"], "No stress, emotion or goal in the log.");
  explanations_section(out, log);
  out << "<p class=\"meta\" id=\"versions\"></p>\n<script>\nconst alplanSpecs = " << script_json(specs) << ";\n"
      << kDrawCharts << "</script>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace alplan::report
