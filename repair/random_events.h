// Random exogenous events for the world simulator (world_simulator.h),
// drawn among those a given plan makes possible, so that they matter to it.
// Seeded: the same options, plan and problem give the same events, so every
// strategy meets the same failures (bench repair's paired design).
//
// The failure kinds a repair study needs, told apart by how the robot
// learns of them (repair/observation.h):
// - arrival: an object without an IoT tag that the plan will carry becomes
//   unavailable; the robot finds out when it reaches the room;
// - iot: an IoT-tagged object the plan will carry becomes unavailable and
//   its tag says so at once;
// - sibling: as in the paper's Scenarios 1 and 2, every object of the
//   carried one's category in its room becomes unavailable (the carried one
//   untagged), and an object of a sibling type (the ontology's augmented
//   types: a mug for a glass) that the problem does not list stands in that
//   room, or in a room the robot passes on its way there;
// - moves: the senior to be served walks to another private room;
// - emotion: that senior's emotion changes, so the goal changes;
// - overrun: a move takes longer than planned;
// - two: two failures of different kinds in one run;
// and two older ones: unavailable (any carried object, a sibling beside it
// half the time) and appears (a new object, no failure).
// Each draw picks uniformly among the requested kinds that the plan gives
// an occasion for, and says which it drew; with none, nothing is drawn.
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

enum class RandomEventKind : unsigned char {
  Unavailable, NewObject, SeniorMoves, EmotionChanges, Overrun, FailsOnArrival, FailsIotReported, SiblingPresent,
  TwoFailures
};

// "unavailable", "appears", "moves", "emotion", "overrun", "arrival", "iot",
// "sibling", "two".
std::string to_string(RandomEventKind kind);
std::optional<RandomEventKind> random_event_kind(const std::string& name);
std::vector<RandomEventKind> all_random_event_kinds();
// The kinds of the repair study: arrival, iot, sibling, moves, emotion,
// overrun, two.
std::vector<RandomEventKind> study_event_kinds();

struct RandomEventOptions {
  std::uint64_t seed = 1;
  std::vector<RandomEventKind> kinds = study_event_kinds();
  // With Unavailable: the chance that an object of a sibling type (the
  // ontology's augmented types) appears where the lost one was.
  double sibling_appears = 0.5;
  double overrun_min = 10.0, overrun_max = 60.0;  // rounded to whole units
  // The domain's vocabulary; the assisted-living domain's by default.
  std::string carry_schema = "carry";
  std::string move_schema = "move";
  std::set<std::string> handover_schemas{"give", "suggest_entertainment2"};  // (robot senior item location)
  std::set<std::string> senior_room_types{"bedroom", "sunroom"};
  std::string iot_predicate = "iot_tagged";
  // Emotions and the window predicate each needs open: a senior whose
  // emotion changes gets the new emotion's window if it was closed.
  std::vector<std::string> emotions{"terrified", "sad", "bored"};
  std::map<std::string, std::string> emotion_windows{
      {"terrified", "hydration_time"}, {"sad", "comfort_time"}, {"bored", "comfort_time"}};
};

// One draw: its kind and the events that make it.
struct RandomFailure {
  RandomEventKind kind = RandomEventKind::Overrun;
  std::vector<ExogenousEvent> events;
};

class RandomEventGenerator {
 public:
  explicit RandomEventGenerator(RandomEventOptions options);

  // One failure against `plan`, made for `problem` (its objects, types,
  // IoT tags and initial state). `serial` numbers new objects (mug_new1,
  // ...). Nothing when the plan offers no occasion for any requested kind.
  std::optional<RandomFailure> draw_failure(const ExecutingPlan& plan, const pddl::Problem& problem,
                                            const TypeOntology* ontology, int serial);
  // The events of draw_failure, or none.
  std::vector<ExogenousEvent> draw(const ExecutingPlan& plan, const pddl::Problem& problem,
                                   const TypeOntology* ontology, int serial);

 private:
  struct PlanSteps;
  double uniform(double lo, double hi);
  std::size_t index(std::size_t size);
  std::vector<RandomEventKind> possible(const PlanSteps& steps, const pddl::Problem& problem,
                                        const TypeOntology* ontology, const std::vector<RandomEventKind>& kinds) const;
  std::vector<ExogenousEvent> events_of(RandomEventKind kind, const PlanSteps& steps, const pddl::Problem& problem,
                                        const TypeOntology* ontology, int serial);
  std::vector<const ScheduledAction*> carries(const PlanSteps& steps, const pddl::Problem& problem,
                                              std::optional<bool> iot) const;
  std::vector<ExogenousEvent> fails(const PlanSteps& steps, const pddl::Problem& problem, bool iot);
  std::vector<ExogenousEvent> sibling_present(const PlanSteps& steps, const pddl::Problem& problem,
                                              const TypeOntology& ontology, int serial);
  std::vector<ExogenousEvent> two_failures(const PlanSteps& steps, const pddl::Problem& problem,
                                           const TypeOntology* ontology, int serial);
  std::vector<std::string> siblings(const pddl::Problem& problem, const TypeOntology& ontology,
                                    const std::string& object) const;
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
