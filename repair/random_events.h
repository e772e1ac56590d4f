// Random exogenous events for the world simulator (world_simulator.h): the
// issue's five kinds — an object becomes unavailable, a new (non-IoT) object
// appears at a location, a senior moves, an emotion changes, an action takes
// longer than planned — drawn among those a given plan makes possible, so
// that they matter to it. Seeded: the same options, plan and problem give
// the same events, so strategies can be compared on the same failures.
//
// Each kind in `kinds` is equally likely; a kind the plan gives no occasion
// for (no carry to spoil, no senior to move) becomes an overrun of one of
// its moves. With the default kinds and the same seed the draws are those
// `bench repair` made before this file existed, so recorded results stay
// reproducible.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/executing_plan.h"
#include "repair/type_ontology.h"
#include "repair/world_simulator.h"

namespace alplan::repair {

enum class RandomEventKind : unsigned char { Unavailable, NewObject, SeniorMoves, EmotionChanges, Overrun };

// "unavailable", "appears", "moves", "emotion", "overrun".
std::string to_string(RandomEventKind kind);
std::optional<RandomEventKind> random_event_kind(const std::string& name);
std::vector<RandomEventKind> all_random_event_kinds();

struct RandomEventOptions {
  std::uint64_t seed = 1;
  std::vector<RandomEventKind> kinds{RandomEventKind::Unavailable, RandomEventKind::SeniorMoves,
                                     RandomEventKind::Overrun};
  // With Unavailable: the chance that an object of a sibling type (the
  // ontology's augmented types) appears where the lost one was.
  double sibling_appears = 0.5;
  double overrun_min = 10.0, overrun_max = 60.0;  // rounded to whole units
  // The domain's vocabulary; the assisted-living domain's by default.
  std::string carry_schema = "carry";
  std::string move_schema = "move";
  std::set<std::string> handover_schemas{"give", "suggest_entertainment2"};  // (robot senior item location)
  std::set<std::string> senior_room_types{"bedroom", "sunroom"};
  // Emotions and the window predicate each needs open: a senior whose
  // emotion changes gets the new emotion's window if it was closed.
  std::vector<std::string> emotions{"terrified", "sad", "bored"};
  std::map<std::string, std::string> emotion_windows{
      {"terrified", "hydration_time"}, {"sad", "comfort_time"}, {"bored", "comfort_time"}};
};

class RandomEventGenerator {
 public:
  explicit RandomEventGenerator(RandomEventOptions options);

  // The events of one failure against `plan`, made for `problem` (its
  // objects, types and initial state). `serial` numbers new objects
  // (mug_new1, ...). Empty when the plan offers nothing to disturb.
  std::vector<ExogenousEvent> draw(const ExecutingPlan& plan, const pddl::Problem& problem,
                                   const TypeOntology* ontology, int serial);

 private:
  struct PlanSteps;
  double uniform(double lo, double hi);
  std::size_t index(std::size_t size);
  std::vector<ExogenousEvent> unavailable(const PlanSteps& steps, const pddl::Problem& problem,
                                          const TypeOntology* ontology, int serial);
  std::vector<ExogenousEvent> new_object(const PlanSteps& steps, const TypeOntology* ontology, int serial);
  std::vector<ExogenousEvent> senior_moves(const PlanSteps& steps, const pddl::Problem& problem);
  std::vector<ExogenousEvent> emotion_changes(const PlanSteps& steps, const pddl::Problem& problem);
  std::vector<ExogenousEvent> overrun(const PlanSteps& steps);

  RandomEventOptions options_;
  std::mt19937_64 random_;
};

}  // namespace alplan::repair
