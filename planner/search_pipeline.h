// Runs a search configuration (search_configuration.h) on one task. The
// configuration becomes a list of phases: the phases of a `then` in order,
// then, in anytime mode, a search around the best plan when `improve=`
// asks for one (plan_neighbourhood_search.h; again around each better plan
// it finds), and weighted A* with each weight under the best plan's value. A phase is one leaf engine or a portfolio of them taking turns, one
// expansion each, in a search space of its own. A phase ends with a plan, by
// exhaustion, by its budget (the next phase runs) or at a limit (the run
// stops). Once a plan is found the first phases stop; anytime phases go on.
//
// What an exhausted run proves (PipelineOutcome::proof): that the goal is
// unreachable from the root, when the sound relaxation says so; or that no
// plan exists, when a complete engine exhausted its space and nothing in the
// task keeps that from being a proof (proof_limits).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "planner/goal_orders.h"
#include "planner/heuristic.h"
#include "planner/linear_metric.h"
#include "planner/search_configuration.h"
#include "planner/search_engine.h"
#include "planner/search_space.h"

namespace alplan {

struct PipelineLimits {
  SearchDeadline deadline;
  double time_limit = std::numeric_limits<double>::infinity();  // for the phases' time shares
  std::size_t node_limit = std::numeric_limits<std::size_t>::max();
  std::size_t address_space_limit = 0;  // bytes; 0: none
  double epsilon = 0.001;
};

struct PipelineContext {
  const TaskIndex& index;
  const SearchStart& start;
  // The task's metric when it only grows (linear_metric.h): bounds anytime
  // phases and orders weighted A* by the metric. Null otherwise.
  std::shared_ptr<const LinearMetric> metric;
  // Goal orders, for the engines that prune by them (null: none).
  std::shared_ptr<const GoalOrders> orders;
  // The heuristic an engine asks for (one per specification, shared).
  std::function<Heuristic&(const HeuristicSpec&, bool metric_order)> heuristic;
  PipelineLimits limits;
};

// Which limit stopped a search, so that each is reported in its own words.
enum class StoppingLimit { None, Time, Nodes, Memory };

struct PipelineOutcome {
  bool stopped_at_limit = false;  // time, nodes or memory
  StoppingLimit limit = StoppingLimit::None;
  std::string proof;              // why no plan exists; empty: no proof
  // The proof is an exhausted complete search, which holds for plans whose
  // dependent happenings are the search's epsilon apart (not the relaxation
  // or the grounding, which hold for any gap).
  bool proof_by_search = false;
  std::string not_proven;         // why an exhausted search is no proof
  SearchStatistics statistics;
  // The search a limit stopped, handed over unfreed (planner.h says why).
  std::shared_ptr<void> memory;
};

// What a solution bounds the later anytime phases by: the plan's metric as
// printed, which the pipeline lowers to the metric at the search's own
// times; or, with `objective` set, the best value the caller measures its
// plans by (PlannerOptions::Objective, of which the metric is a lower
// bound), lowered by as much as this plan's printed metric (`printed`)
// exceeds its metric at the search's times. Without that lowering a later
// phase meets the same plan again, under the bound, and ends on it.
struct SolutionValue {
  double value = 0.0;
  bool objective = false;
  double printed = 0.0;  // with `objective`: the plan's metric as printed
};

// Called with each solution and the engine that found it; returns what each
// later plan must beat, or nullopt to stop the run.
using SolutionHandler = std::function<std::optional<SolutionValue>(const Solution&, const std::string& engine)>;

// Why an exhausted complete search is not a proof for this task ("" when it
// is): only the shortest and longest durations of an action whose effects
// or conditions read ?duration are tried; with continuous change a state
// holds the values of one schedule among many; a PDDL 3 `always` check may
// refuse a state between two snaps VAL would see as one happening.
std::string proof_limits(const TaskIndex& index);

PipelineOutcome run_pipeline(const SearchConfiguration& configuration, const PipelineContext& context,
                             const SolutionHandler& on_solution);

}  // namespace alplan
