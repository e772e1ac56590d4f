#include "home/home_problem.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "domains/emotion_goals.h"
#include "domains/home_generator.h"
#include "home/robot_dispatch.h"
#include "pddl_parser/writer.h"
#include "repair/reformulation.h"

namespace alplan::home {
namespace {

// The domain the run plans with: the paper's, or its battery variant.
std::string domain_file(const HomeSettings& s) {
  return s.domains_dir + (s.battery ? "/battery/domain.pddl" : "/domain.pddl");
}

// With batteries, the home's problem gains what it lacks of them.
domains::LoadedHome with_batteries(domains::LoadedHome home, const HomeSettings& s) {
  if (!s.battery) return home;
  pddl::Problem problem = *home.files.problem;
  domains::add_batteries(problem, s.battery_options);
  home.files.problem = std::make_shared<const pddl::Problem>(std::move(problem));
  return home;
}

domains::LoadedHome load_files(const HomeSettings& s) {
  const std::string ontology = s.domains_dir + "/types.ttl";
  if (s.generate_seniors > 0) {
    domains::HomeOptions options;
    options.seniors = s.generate_seniors;
    options.robots = s.generate_robots;
    if (s.generate_rooms > 0) options.rooms = s.generate_rooms;
    if (s.generate_objects > 0) options.objects = s.generate_objects;
    options.stressed = 1;  // the generator wants one; calm_problem takes every emotion away
    options.seed = s.seed;
    const domains::GeneratedHome generated = domains::generate_home(options);
    domains::LoadedHome paper = domains::load_home_files(domain_file(s), s.domains_dir + "/home.pddl", ontology);
    domains::LoadedFiles files = domains::load_pddl_text(pddl::write_domain(*paper.files.domain), "domain.pddl",
                                                         generated.problem, "generated-home.pddl");
    return {std::move(files), std::move(paper.ontology), std::move(paper.domain)};
  }
  const std::string file = s.home_file.empty() ? s.domains_dir + "/home.pddl" : s.home_file;
  return domains::load_home_files(domain_file(s), file, ontology);
}

// Whether `type` is `ancestor` or declared below it in the domain.
bool type_is_a(const pddl::Domain& domain, std::string type, const std::string& ancestor) {
  for (std::size_t depth = 0; depth <= domain.types.size(); ++depth) {  // a cycle cannot loop for ever
    if (type == ancestor) return true;
    const auto d = std::find_if(domain.types.begin(), domain.types.end(),
                                [&](const pddl::TypeDeclaration& t) { return t.name == type; });
    if (d == domain.types.end() || d->parents.empty()) return false;
    type = d->parents.front();
  }
  return false;
}

// The settings' devices join the home's problem, each where it stands.
domains::LoadedHome with_devices(domains::LoadedHome home, const HomeSettings& s) {
  if (s.devices.empty()) return home;
  pddl::Problem problem = *home.files.problem;
  for (const HomeDevice& d : s.devices) {
    if (!is_device_type(d.type)) {
      throw std::invalid_argument("device " + d.name + ": type " + d.type + " is not speaker, lamp or tv");
    }
    if (repair::object_type(problem, d.name)) throw std::invalid_argument("device " + d.name + ": the home has it already");
    const std::optional<std::string> room = repair::object_type(problem, d.room);
    if (!room || !type_is_a(home.domain, *room, "location")) {
      throw std::invalid_argument("device " + d.name + ": " + d.room + " is not a room of the home");
    }
    pddl::TypedName object;
    object.name = d.name;
    object.types = {d.type};
    problem.objects.push_back(object);
    pddl::Atom at;
    at.name = "be";
    at.args.resize(2);
    at.args[0].name = d.name;
    at.args[1].name = d.room;
    problem.init.push_back(at);
  }
  home.files.problem = std::make_shared<const pddl::Problem>(std::move(problem));
  return home;
}

// What answers each emotion at once (the domain's device actions).
const char* device_type_for(const std::string& emotion) {
  if (emotion == "terrified") return "speaker";
  if (emotion == "sad") return "lamp";
  return "tv";
}

}  // namespace

bool is_device_type(const std::string& type) { return type == "speaker" || type == "lamp" || type == "tv"; }

LoadedRun load_run(const HomeSettings& s) {
  domains::LoadedHome home = with_devices(with_batteries(load_files(s), s), s);
  HomeMap map = read_home_map(*home.files.problem);
  return {std::move(home), std::move(map)};
}

// The home's problem with nothing to do: no emotion, window or goal yet.
pddl::Problem calm_problem(const pddl::Problem& problem) {
  pddl::Problem out = problem;
  const auto about_moods = [](const pddl::Atom& a) {
    for (const char* p : {"terrified", "sad", "bored", "hydration_time", "comfort_time", "soothed", "cheerful",
                          "entertained", "reassured"}) {
      if (a.name == p) return true;
    }
    return false;
  };
  out.init.erase(std::remove_if(out.init.begin(), out.init.end(), about_moods), out.init.end());
  out.timed_literals.clear();
  pddl::Condition none;
  none.kind = pddl::Condition::Kind::And;
  out.goal = none;
  return out;
}

std::string robot_of(const std::string& action, const HomeMap& map) {
  std::istringstream words(action.size() > 2 ? action.substr(1, action.size() - 2) : action);
  for (std::string w; words >> w;) {
    if (map.has_robot(w)) return w;
  }
  return {};
}

nlohmann::json steps_json(const repair::ExecutingPlan& plan, const HomeMap& map, const std::set<std::string>& devices) {
  nlohmann::json steps = nlohmann::json::array();
  for (const repair::ScheduledAction& s : plan.steps) {
    nlohmann::json step = {{"start", s.start}, {"duration", s.duration}, {"action", s.name}, {"robot", robot_of(s.name, map)}};
    if (const std::string device = device_of(s.name, devices); !device.empty()) step["device"] = device;
    steps.push_back(std::move(step));
  }
  return steps;
}

void require_return(pddl::Problem& problem, const std::vector<std::string>& robots,
                    const std::map<std::string, double>& return_levels) {
  pddl::Condition all;
  all.kind = pddl::Condition::Kind::And;
  if (problem.goal) all.children.push_back(*problem.goal);
  for (const std::string& r : robots) {
    pddl::Condition enough;
    enough.kind = pddl::Condition::Kind::Comparison;
    enough.comparison = pddl::Comparison::GreaterEqual;
    pddl::NumericExpression level, at_least;
    level.kind = pddl::NumericExpression::Kind::Function;
    level.function.name = "battery";
    level.function.args.resize(1);
    level.function.args[0].name = r;
    at_least.value = return_levels.at(r);
    enough.expressions = {level, at_least};
    all.children.push_back(enough);
  }
  problem.goal = all;
}

repair::ObservationOptions home_observation_options(const HomeSettings& settings) {
  repair::ObservationOptions o;
  const auto model = repair::observation_model(settings.observe);
  if (!model) throw std::invalid_argument("--observe " + settings.observe + ": not full, iot or camera");
  o.model = *model;
  return o;
}

repair::RandomEventOptions home_event_options(const HomeSettings& settings) {
  repair::RandomEventOptions o;
  o.seed = settings.seed * 7919 + 17;
  o.kinds.clear();
  for (const std::string& k : settings.failure_kinds) {
    if (k == "robot_down") continue;  // the home's own (robot_faults.h)
    const auto kind = repair::random_event_kind(k);
    if (!kind) throw std::invalid_argument("failure kind " + k + ": not one of the repair study's kinds nor robot_down");
    o.kinds.push_back(*kind);
  }
  return o;
}

PlannerOptions home_planner_options(const HomeSettings& settings) {
  PlannerOptions planner = repair::executing_planner_options();
  // One evaluation per expansion, not one per child: the anytime weights
  // cost a sixth of the time with the same outcomes (1 h of the large home,
  // home/README.md). EHC's own budget counts expansions; EHC stores about
  // two nodes per expansion on the home's relevant actions (~16 children
  // each), so a fifth of the node limit leaves the fallback searches room.
  SearchShorthands search;
  search.knobs.deferred = true;
  search.knobs.ehc_expansions = std::min<std::uint64_t>(search.knobs.ehc_expansions, settings.planner_node_limit / 5);
  search.anytime = settings.planner_expansions > 0;
  search.anytime_min_weight = 3.0;
  search.anytime_expansions = settings.planner_expansions;
  planner.search = configuration_from(search);
  planner.time_limit = settings.planning_time;
  planner.node_limit = settings.planner_node_limit;
  planner.epsilon = 0.002;
  // In real time the world goes on while the planner thinks: no step
  // starts before the planning budget has passed.
  planner.reserve_planning_time = settings.live;
  return planner;
}

PlannerOptions home_replanner_options(const HomeSettings& settings) {
  // Repairs and merges answer a world that has changed under a running
  // plan: their first plan goes out, improved only as far as this allows.
  HomeSettings first_plan = settings;
  first_plan.planner_expansions = settings.replan_expansions;
  return home_planner_options(first_plan);
}

void write_unplanned(const std::string& dir, int n, const pddl::Problem& problem, const pddl::Domain& domain,
                     double now) {
  std::filesystem::create_directories(dir);
  pddl::Problem from_now = problem;
  for (pddl::TimedInitialLiteral& til : from_now.timed_literals) til.time -= now;
  if (from_now.constraints) repair::shift_constraint_times(*from_now.constraints, now);  // preferred windows
  std::erase_if(from_now.timed_literals, [](const pddl::TimedInitialLiteral& til) { return til.time <= 0.0; });
  std::ofstream(dir + "/unplanned-" + std::to_string(n) + ".pddl")
      << "; planned at " << now << " s of the run; times below are from then\n" << pddl::write_problem(from_now);
  if (n == 1) std::ofstream(dir + "/domain.pddl") << pddl::write_domain(domain);
}

std::vector<std::pair<repair::AtomKey, bool>> told_facts(const PerceivedGoal& g) {
  std::vector<std::pair<repair::AtomKey, bool>> facts;
  for (const char* e : {"terrified", "sad", "bored"}) facts.push_back({{e, g.senior}, g.emotion == e});
  for (const char* p : {"soothed", "cheerful", "entertained", "reassured"}) facts.push_back({{p, g.senior}, false});
  facts.push_back({{g.window, g.senior}, true});
  return facts;
}

std::optional<std::string> answering_device(const PerceivedGoal& g, const pddl::Problem& home,
                                           const repair::WorldState& believed) {
  const TravelTimes places(believed_places(believed));
  const std::optional<std::string> room = places.room_of(g.senior);
  if (!room) return std::nullopt;
  const std::string wanted = device_type_for(g.emotion);
  for (const pddl::TypedName& o : home.objects) {
    if (o.types.empty() || o.types.front() != wanted || places.room_of(o.name) != room) continue;
    if (wanted == "tv" && !believed.holds({"available", o.name})) continue;  // in use
    return o.name;
  }
  return std::nullopt;
}

void ask_device_response(PerceivedGoal& g) {
  pddl::Condition both;
  both.kind = pddl::Condition::Kind::And;
  both.children = {g.goal, domains::senior_condition("reassured", g.senior)};
  g.goal = both;
}

void drop_device_response(PerceivedGoal& g) {
  if (g.device.empty()) return;
  pddl::Condition perceived = g.goal.children.front();
  g.goal = std::move(perceived);
  g.device.clear();
}

std::string device_of(const std::string& action, const std::set<std::string>& devices) {
  std::istringstream words(action.size() > 2 ? action.substr(1, action.size() - 2) : action);
  std::string schema, first;
  if (!(words >> schema >> first) || !devices.count(first)) return {};
  return first;
}

pddl::TimedInitialLiteral window_close(const PerceivedGoal& g) {
  pddl::TimedInitialLiteral til;
  til.time = g.window_end;
  til.positive = false;
  til.atom = domains::senior_atom(g.window, g.senior);
  return til;
}

pddl::Problem believed_places(const repair::WorldState& believed) {
  pddl::Problem p;
  for (const repair::AtomKey& a : believed.atoms) {
    if (a.front() == "be" || a.front() == "path") p.init.push_back(repair::atom_of(a));
  }
  for (const auto& [key, value] : believed.values) {
    if (key.front() != "moving_time") continue;
    pddl::NumericFact f;
    f.function = repair::atom_of(key);
    f.value = value;
    p.numeric_init.push_back(f);
  }
  return p;
}

void prefer_windows(pddl::Problem& problem, const std::optional<pddl::Metric>& base,
                    const std::vector<PerceivedGoal>& goals, double now, const HomeSettings& settings) {
  using Expression = pddl::NumericExpression;
  pddl::Condition preferences;
  preferences.kind = pddl::Condition::Kind::And;
  Expression sum;
  sum.kind = Expression::Kind::Add;
  if (base) sum.operands.push_back(base->expression);
  for (const PerceivedGoal& g : goals) {
    if (g.window_end <= now) continue;
    pddl::Condition within;
    within.kind = pddl::Condition::Kind::Within;
    within.numbers = {g.window_end};
    within.children = {g.goal};
    pddl::Condition preference;
    preference.kind = pddl::Condition::Kind::Preference;
    preference.preference_name = "late-" + g.senior;
    preference.children = {within};
    preferences.children.push_back(preference);
    Expression violated, cost, term;
    violated.kind = Expression::Kind::IsViolated;
    violated.function.name = preference.preference_name;
    cost.value = settings.weight_of(g.emotion) * settings.window_cost_s;
    term.kind = Expression::Kind::Multiply;
    term.operands = {cost, violated};
    sum.operands.push_back(term);
  }
  if (preferences.children.empty()) {
    problem.constraints.reset();
    problem.metric = base;
    return;
  }
  problem.constraints = preferences;
  pddl::Metric metric = base.value_or(pddl::Metric{});
  metric.minimize = true;
  metric.expression = sum;
  problem.metric = metric;
}

}  // namespace alplan::home
