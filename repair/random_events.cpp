#include "repair/random_events.h"

#include <algorithm>
#include <cmath>

#include "repair/reformulation.h"

namespace alplan::repair {
namespace {

constexpr std::pair<RandomEventKind, const char*> kNames[] = {
    {RandomEventKind::Unavailable, "unavailable"},   {RandomEventKind::NewObject, "appears"},
    {RandomEventKind::SeniorMoves, "moves"},         {RandomEventKind::EmotionChanges, "emotion"},
    {RandomEventKind::Overrun, "overrun"},           {RandomEventKind::FailsOnArrival, "arrival"},
    {RandomEventKind::FailsIotReported, "iot"},      {RandomEventKind::SiblingPresent, "sibling"},
    {RandomEventKind::TwoFailures, "two"},
};

// The index-th word of "(carry robot1 glass_id05 kitchen1)": 0 the schema.
std::string word(const std::string& name, std::size_t index) {
  const AtomKey words = words_of(name);
  return index < words.size() ? words[index] : std::string();
}

bool holds(const pddl::Problem& problem, const std::string& predicate, const std::string& object) {
  return std::any_of(problem.init.begin(), problem.init.end(), [&](const pddl::Atom& a) {
    return a.name == predicate && a.args.size() == 1 && a.args.front().name == object;
  });
}

}  // namespace

std::string to_string(RandomEventKind kind) {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "?";
}

std::optional<RandomEventKind> random_event_kind(const std::string& name) {
  for (const auto& [k, n] : kNames) {
    if (name == n) return k;
  }
  return std::nullopt;
}

std::vector<RandomEventKind> all_random_event_kinds() {
  std::vector<RandomEventKind> all;
  for (const auto& [k, name] : kNames) all.push_back(k);
  return all;
}

std::vector<RandomEventKind> study_event_kinds() {
  using K = RandomEventKind;
  return {K::FailsOnArrival, K::FailsIotReported, K::SiblingPresent, K::SeniorMoves,
          K::EmotionChanges, K::Overrun,          K::TwoFailures};
}

// The steps of the plan each kind of event can hit.
struct RandomEventGenerator::PlanSteps {
  std::vector<const ScheduledAction*> carries, handovers, moves;
  // When the plan runs: events are drawn within it, not before it began (a
  // home plans at any time of its day; the study's plans start at 0).
  double begin = 0.0, end = 0.0;
};

RandomEventGenerator::RandomEventGenerator(RandomEventOptions options)
    : options_(std::move(options)), random_(options_.seed) {}

double RandomEventGenerator::uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(random_);
}

std::size_t RandomEventGenerator::index(std::size_t size) {
  return std::uniform_int_distribution<std::size_t>(0, size - 1)(random_);
}

std::vector<ExogenousEvent> RandomEventGenerator::draw(const ExecutingPlan& plan, const pddl::Problem& problem,
                                                       const TypeOntology* ontology, int serial) {
  std::optional<RandomFailure> failure = draw_failure(plan, problem, ontology, serial);
  return failure ? failure->events : std::vector<ExogenousEvent>{};
}

std::optional<RandomFailure> RandomEventGenerator::draw_failure(const ExecutingPlan& plan, const pddl::Problem& problem,
                                                                const TypeOntology* ontology, int serial) {
  PlanSteps steps;
  steps.begin = plan.steps.empty() ? 0.0 : plan.steps.front().start;
  for (const ScheduledAction& s : plan.steps) {
    steps.begin = std::min(steps.begin, s.start);
    const std::string schema = word(s.name, 0);
    if (schema == options_.carry_schema) steps.carries.push_back(&s);
    if (options_.handover_schemas.count(schema)) steps.handovers.push_back(&s);
    if (schema == options_.move_schema) steps.moves.push_back(&s);
    steps.end = std::max(steps.end, s.end());
  }
  const std::vector<RandomEventKind> kinds = possible(steps, problem, ontology, options_.kinds);
  if (kinds.empty()) return std::nullopt;
  RandomFailure failure;
  failure.kind = kinds[index(kinds.size())];
  failure.events = events_of(failure.kind, steps, problem, ontology, serial);
  return failure;
}

std::vector<RandomEventKind> RandomEventGenerator::possible(const PlanSteps& steps, const pddl::Problem& problem,
                                                            const TypeOntology* ontology,
                                                            const std::vector<RandomEventKind>& kinds) const {
  using K = RandomEventKind;
  std::vector<K> out;
  for (K kind : kinds) {
    bool occasion = false;
    switch (kind) {
      case K::Unavailable: occasion = !steps.carries.empty(); break;
      case K::NewObject: occasion = ontology && !ontology->augmented().empty() &&
                                    (!steps.carries.empty() || !steps.handovers.empty()); break;
      case K::SeniorMoves:
      case K::EmotionChanges: occasion = !steps.handovers.empty(); break;
      case K::Overrun: occasion = !steps.moves.empty(); break;
      case K::FailsOnArrival: occasion = !carries(steps, problem, false).empty(); break;
      case K::FailsIotReported: occasion = !carries(steps, problem, true).empty(); break;
      case K::SiblingPresent: {
        for (const ScheduledAction* c : carries(steps, problem, false)) {
          occasion = occasion || (ontology && !siblings(problem, *ontology, word(c->name, 2)).empty());
        }
        break;
      }
      case K::TwoFailures: {
        std::vector<K> others;
        for (K k : kinds) {
          if (k != K::TwoFailures) others.push_back(k);
        }
        occasion = possible(steps, problem, ontology, others).size() >= 2;
        break;
      }
    }
    if (occasion) out.push_back(kind);
  }
  return out;
}

std::vector<ExogenousEvent> RandomEventGenerator::events_of(RandomEventKind kind, const PlanSteps& steps,
                                                            const pddl::Problem& problem, const TypeOntology* ontology,
                                                            int serial) {
  using K = RandomEventKind;
  switch (kind) {
    case K::Unavailable: return unavailable(steps, problem, ontology, serial);
    case K::NewObject: return new_object(steps, ontology, serial);
    case K::SeniorMoves: return senior_moves(steps, problem);
    case K::EmotionChanges: return emotion_changes(steps, problem);
    case K::Overrun: return overrun(steps);
    case K::FailsOnArrival: return fails(steps, problem, false);
    case K::FailsIotReported: return fails(steps, problem, true);
    case K::SiblingPresent: return sibling_present(steps, problem, *ontology, serial);
    case K::TwoFailures: return two_failures(steps, problem, ontology, serial);
  }
  return {};
}

// The carries of objects with (iot true) or without (false) an IoT tag.
std::vector<const ScheduledAction*> RandomEventGenerator::carries(const PlanSteps& steps, const pddl::Problem& problem,
                                                                  std::optional<bool> iot) const {
  std::vector<const ScheduledAction*> out;
  for (const ScheduledAction* c : steps.carries) {
    if (!iot || holds(problem, options_.iot_predicate, word(c->name, 2)) == *iot) out.push_back(c);
  }
  return out;
}

std::vector<std::string> RandomEventGenerator::siblings(const pddl::Problem& problem, const TypeOntology& ontology,
                                                        const std::string& object) const {
  const std::string type = object_type(problem, object).value_or("");
  std::vector<std::string> out;
  for (const std::string& a : ontology.augmented()) {
    if (ontology.parent(a) == ontology.parent(type)) out.push_back(a);
  }
  return out;
}

// A carried object, tagged or not, becomes unavailable before the carry.
std::vector<ExogenousEvent> RandomEventGenerator::fails(const PlanSteps& steps, const pddl::Problem& problem, bool iot) {
  const std::vector<const ScheduledAction*> candidates = carries(steps, problem, iot);
  if (candidates.empty()) return {};
  const ScheduledAction& carry = *candidates[index(candidates.size())];
  return {becomes_unavailable(uniform(steps.begin, std::max(steps.begin, carry.start - 0.001)), word(carry.name, 2))};
}

// An untagged carried object fails; an object of a sibling type stands
// from the start in the pickup room or in a room the robot enters on its
// way there (the moves before the carry).
std::vector<ExogenousEvent> RandomEventGenerator::sibling_present(const PlanSteps& steps, const pddl::Problem& problem,
                                                                  const TypeOntology& ontology, int serial) {
  std::vector<const ScheduledAction*> candidates;
  for (const ScheduledAction* c : carries(steps, problem, false)) {
    if (!siblings(problem, ontology, word(c->name, 2)).empty()) candidates.push_back(c);
  }
  if (candidates.empty()) return {};
  const ScheduledAction& carry = *candidates[index(candidates.size())];
  const std::string object = word(carry.name, 2);
  std::vector<std::string> rooms{word(carry.name, 3)};
  for (const ScheduledAction* m : steps.moves) {
    const std::string to = word(m->name, 3);
    if (m->end() <= carry.start && std::find(rooms.begin(), rooms.end(), to) == rooms.end()) rooms.push_back(to);
  }
  const std::vector<std::string> types = siblings(problem, ontology, object);
  const std::string type = types[index(types.size())];
  const std::string room = uniform(0.0, 1.0) < 0.5 ? rooms.front() : rooms[index(rooms.size())];
  const double at = uniform(steps.begin, std::max(steps.begin, carry.start - 0.001));
  // As in the paper's Scenarios 1 and 2: every object of that category in
  // the pickup room is taken, not only the one the plan needs.
  const std::optional<std::string> category = ontology.parent(object_type(problem, object).value_or(""));
  std::vector<ExogenousEvent> events;
  for (const pddl::Atom& a : problem.init) {
    if (a.name != "be" || a.args.size() != 2 || a.args[1].name != word(carry.name, 3)) continue;
    const std::string& other = a.args[0].name;
    if (other == object || ontology.parent(object_type(problem, other).value_or("")) == category) {
      events.push_back(becomes_unavailable(at, other));
    }
  }
  events.push_back(object_appears(0.0, {type + "_new" + std::to_string(serial), type, room, 1.0}));
  return events;
}

std::vector<ExogenousEvent> RandomEventGenerator::two_failures(const PlanSteps& steps, const pddl::Problem& problem,
                                                               const TypeOntology* ontology, int serial) {
  std::vector<RandomEventKind> others;
  for (RandomEventKind k : options_.kinds) {
    if (k != RandomEventKind::TwoFailures) others.push_back(k);
  }
  std::vector<RandomEventKind> kinds = possible(steps, problem, ontology, others);
  if (kinds.size() < 2) return {};
  const std::size_t first = index(kinds.size());
  std::vector<ExogenousEvent> events = events_of(kinds[first], steps, problem, ontology, serial);
  kinds.erase(kinds.begin() + static_cast<std::ptrdiff_t>(first));
  for (ExogenousEvent& e : events_of(kinds[index(kinds.size())], steps, problem, ontology, serial + 100)) {
    events.push_back(std::move(e));
  }
  return events;
}

// An object the plan will carry becomes unavailable before the carry; half
// the time (sibling_appears) an object of a sibling type appears beside it.
std::vector<ExogenousEvent> RandomEventGenerator::unavailable(const PlanSteps& steps, const pddl::Problem& problem,
                                                              const TypeOntology* ontology, int serial) {
  if (steps.carries.empty()) return {};
  const ScheduledAction& carry = *steps.carries[index(steps.carries.size())];
  const std::string object = word(carry.name, 2), room = word(carry.name, 3);
  const double at = uniform(steps.begin, std::max(steps.begin, carry.start - 0.001));
  std::vector<ExogenousEvent> events{becomes_unavailable(at, object)};
  if (!ontology) return events;
  const std::vector<std::string> types = siblings(problem, *ontology, object);
  if (!types.empty() && uniform(0.0, 1.0) < options_.sibling_appears) {
    const std::string t = types[index(types.size())];
    events.push_back(object_appears(at, {t + "_new" + std::to_string(serial), t, room, 1.0}));
  }
  return events;
}

// A new object of one of the ontology's augmented types (one no IoT device
// reports) appears where the plan picks something up, or by the senior.
std::vector<ExogenousEvent> RandomEventGenerator::new_object(const PlanSteps& steps, const TypeOntology* ontology,
                                                             int serial) {
  if (!ontology || ontology->augmented().empty()) return {};
  std::string room;
  if (!steps.carries.empty()) room = word(steps.carries[index(steps.carries.size())]->name, 3);
  if (room.empty() && !steps.handovers.empty()) room = word(steps.handovers.front()->name, 4);
  if (room.empty()) return {};
  const std::vector<std::string> types(ontology->augmented().begin(), ontology->augmented().end());
  const std::string type = types[index(types.size())];
  const double at = uniform(steps.begin, steps.end);
  return {object_appears(at, {type + "_new" + std::to_string(serial), type, room, 1.0})};
}

// The senior the plan hands something to walks to another private room
// before the handover.
std::vector<ExogenousEvent> RandomEventGenerator::senior_moves(const PlanSteps& steps, const pddl::Problem& problem) {
  if (steps.handovers.empty()) return {};
  const ScheduledAction& give = *steps.handovers.front();
  const std::string senior = word(give.name, 2), from = word(give.name, 4);
  std::vector<std::string> rooms;
  for (const pddl::TypedName& o : problem.objects) {
    const bool private_room = std::any_of(o.types.begin(), o.types.end(),
                                          [&](const std::string& t) { return options_.senior_room_types.count(t); });
    if (private_room && o.name != from) rooms.push_back(o.name);
  }
  if (rooms.empty()) return {};
  const std::string to = rooms[index(rooms.size())];
  return repair::senior_moves(uniform(steps.begin, give.start), senior, from, to);
}

// The senior the plan comforts feels something else before the handover;
// the window the new emotion needs opens if it was closed.
std::vector<ExogenousEvent> RandomEventGenerator::emotion_changes(const PlanSteps& steps,
                                                                  const pddl::Problem& problem) {
  if (steps.handovers.empty()) return {};
  const ScheduledAction& give = *steps.handovers.front();
  const std::string senior = word(give.name, 2);
  std::string from;
  for (const std::string& e : options_.emotions) {
    if (from.empty() && holds(problem, e, senior)) from = e;
  }
  std::vector<std::string> others;
  for (const std::string& e : options_.emotions) {
    if (e != from) others.push_back(e);
  }
  if (from.empty() || others.empty()) return {};
  const std::string to = others[index(others.size())];
  const double at = uniform(steps.begin, give.start);
  std::vector<ExogenousEvent> events = repair::emotion_changes(at, senior, from, to);
  const auto window = options_.emotion_windows.find(to);
  if (window != options_.emotion_windows.end() && !holds(problem, window->second, senior)) {
    ExogenousEvent open;
    open.time = at;
    open.atom = {window->second, senior};
    open.value = true;
    open.description = events.front().description;
    events.push_back(open);
  }
  return events;
}

// A move the plan makes takes longer than planned.
std::vector<ExogenousEvent> RandomEventGenerator::overrun(const PlanSteps& steps) {
  if (steps.moves.empty()) return {};
  const ScheduledAction& move = *steps.moves[index(steps.moves.size())];
  return {action_overruns(move.name, std::round(uniform(options_.overrun_min, options_.overrun_max)))};
}

}  // namespace alplan::repair
