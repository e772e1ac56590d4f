// The counts `alplan parse` reports for a domain and, optionally, a problem.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"

namespace alplan::pddl {

struct Summary {
  std::string domain_name;
  std::vector<std::string> requirements;
  std::size_t types = 0;
  std::size_t constants = 0;
  std::size_t predicates = 0;
  std::size_t functions = 0;
  std::size_t actions = 0;
  std::size_t durative_actions = 0;
  std::size_t derived_predicates = 0;

  bool has_problem = false;
  std::string problem_name;
  std::size_t objects = 0;
  std::size_t init_facts = 0;
  std::size_t numeric_facts = 0;
  std::size_t timed_literals = 0;
  std::size_t goal_size = 0;  // atoms and comparisons in the goal
  std::string metric;         // "minimize (total-time)", or empty
};

Summary summarize(const Domain& domain, const Problem* problem);

// Literal leaves (atoms, equalities, comparisons) of a condition.
std::size_t count_literals(const Condition& condition);

}  // namespace alplan::pddl
