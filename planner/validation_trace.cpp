#include "planner/validation_trace.h"

#include <algorithm>
#include <cmath>

#include "pddl_parser/writer.h"

namespace alplan {
namespace {

std::string value_text(double value) { return std::isnan(value) ? "undefined" : pddl::format_number(value); }

bool same_value(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

}  // namespace

StateChange state_change(const GroundTask& task, const ExplicitState& before, const ExplicitState& after) {
  StateChange change;
  // The states grow as the validator interns facts: read past either's end
  // as false or undefined, as ExplicitState does.
  const std::size_t facts = std::max(before.facts().size(), after.facts().size());
  for (FactId f = 0; f < facts; ++f) {
    if (before.fact(f) == after.fact(f)) continue;
    (after.fact(f) ? change.added : change.deleted).push_back(task.fact_name(f));
  }
  const std::size_t values = std::max(before.values().size(), after.values().size());
  for (NumericVarId v = 0; v < values; ++v) {
    if (same_value(before.value(v), after.value(v))) continue;
    change.values.push_back(task.variable_name(v) + ": " + value_text(before.value(v)) + " -> " +
                            value_text(after.value(v)));
  }
  return change;
}

std::string format_happening(const GroundTask& task, const HappeningRecord& happening) {
  std::string out = "Happening " + std::to_string(happening.index + 1) + ", time " +
                    pddl::format_number(happening.time) + ":\n";
  for (const std::string& member : happening.members) out += "  " + member + "\n";
  if (happening.before && happening.after) {
    const StateChange change = state_change(task, *happening.before, *happening.after);
    for (const std::string& fact : change.deleted) out += "  deletes " + fact + "\n";
    for (const std::string& fact : change.added) out += "  adds " + fact + "\n";
    for (const std::string& value : change.values) out += "  " + value + "\n";
  }
  for (const Violation& v : happening.violations) out += "  violation: " + v.message() + "\n";
  return out;
}

}  // namespace alplan
