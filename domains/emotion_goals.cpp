#include "domains/emotion_goals.h"

namespace alplan::domains {
namespace {

struct Remedy {
  const char* emotion;
  const char* goal;
};
constexpr Remedy kRemedies[] = {{"terrified", "soothed"}, {"sad", "cheerful"}, {"bored", "entertained"}};

// What the senior's emotion calls for, with the reason.
std::optional<std::pair<pddl::Condition, std::string>> goal_for(const repair::WorldState& observed,
                                                                 const std::string& senior) {
  for (const Remedy& r : kRemedies) {
    if (observed.holds({r.emotion, senior})) return std::make_pair(senior_condition(r.goal, senior), senior + " is " + r.emotion);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string_view> goal_for_emotion(std::string_view emotion) {
  for (const Remedy& r : kRemedies) {
    if (emotion == r.emotion) return r.goal;
  }
  return std::nullopt;
}

pddl::Atom senior_atom(const std::string& predicate, const std::string& senior) {
  pddl::Atom atom;
  atom.name = predicate;
  pddl::Term who;
  who.name = senior;
  atom.args.push_back(who);
  return atom;
}

pddl::Condition senior_condition(const std::string& predicate, const std::string& senior) {
  pddl::Condition condition;
  condition.kind = pddl::Condition::Kind::Atom;
  condition.atom = senior_atom(predicate, senior);
  return condition;
}

GoalGenerator emotion_goal_generator(const std::string& senior) {
  return [senior](const repair::WorldState& observed) { return goal_for(observed, senior); };
}

GoalGenerator emotion_goal_generator(const std::vector<std::string>& seniors) {
  return [seniors](const repair::WorldState& observed) -> std::optional<std::pair<pddl::Condition, std::string>> {
    pddl::Condition all;
    all.kind = pddl::Condition::Kind::And;
    std::string reasons;
    for (const std::string& senior : seniors) {
      if (auto goal = goal_for(observed, senior)) {
        all.children.push_back(goal->first);
        reasons += (reasons.empty() ? "" : " and ") + goal->second;
        continue;
      }
      for (const Remedy& r : kRemedies) {
        if (observed.holds({r.goal, senior})) all.children.push_back(senior_condition(r.goal, senior));
      }
    }
    if (reasons.empty()) return std::nullopt;
    return std::make_pair(all, reasons);
  };
}

}  // namespace alplan::domains
