// libFuzzer target for the PDDL parser, checker and writer.
// Properties checked on any input bytes (also read as a plan file and as a
// search configuration, `alplan plan --search`): no crash, leak, hang or
// undefined behaviour (the sanitizers), and for every input that parses, the
// writer's output parses back to the same AST (for a configuration: its
// printed expression parses back to the same configuration).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"
#include "planner/plan.h"
#include "planner/search_configuration.h"

namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace alplan::pddl;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const DomainParseResult domain = parse_domain(text, "fuzz");
  if (domain.ast) {
    check_domain(*domain.ast, "fuzz");
    if (domain.ok()) {
      const DomainParseResult again = parse_domain(write_domain(*domain.ast), "written");
      require(again.ok() && *again.ast == *domain.ast);
    }
  }
  const ProblemParseResult problem = parse_problem(text, "fuzz");
  if (problem.ast) {
    if (domain.ast) check_problem(*domain.ast, *problem.ast, "fuzz");
    if (problem.ok()) {
      const ProblemParseResult again = parse_problem(write_problem(*problem.ast), "written");
      require(again.ok() && *again.ast == *problem.ast);
    }
  }
  // The plan reader sees the same bytes: it must not crash either.
  const alplan::PlanReadResult plan = alplan::read_plan(text, "fuzz");
  if (plan.ok()) {
    const alplan::PlanReadResult again = alplan::read_plan(alplan::write_plan(plan.plan, 17), "written");
    require(again.ok() && again.plan.steps.size() == plan.plan.steps.size());
  }
  // The search configuration language (planner/search_configuration.h).
  try {
    const alplan::SearchConfiguration c = alplan::parse_search_configuration(text);
    require(alplan::parse_search_configuration(c.to_string()).engine == c.engine);
  } catch (const alplan::SearchConfigurationError&) {
  }
  return 0;
}
