# What `alplan plan` prints (issue 46): JSON on stdout for every outcome,
# input errors included, in one versioned schema; each limit in its own
# words; sequential plans with a cost line for classical tasks, accepted
# back by `validate`; the heuristic named in the plan header; seconds to the
# millisecond. Variables: ALPLAN, SHARED, DATA, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

set(data ${DATA}/planner)
set(train ${SHARED}/benchmarks/ipc/ipc-2008/model-train-temporal-satisficing-numeric-fluents)

# Input errors: an object on stdout too, with the diagnostics.
# (nlohmann::json writes keys in alphabetical order.)
expect_stdout(2 "no-such-file.pddl.*\"schema_version\": 1.*\"status\": \"input_error\""
  ${ALPLAN} plan --json ${data}/no-such-file.pddl ${data}/mixed-problem.pddl)
expect_stdout(2 "unknown engine 'dfs'.*\"status\": \"input_error\""
  ${ALPLAN} plan --json --search dfs ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)
# A limit: which one, and every field of the schema present.
expect_stdout(11 "\"best_index\": null.*\"limit\": \"time\".*\"seconds\": {.*\"statistics\": {"
  ${ALPLAN} plan --json --time-limit 0.3 ${train}/domain.pddl ${train}/instances/instance-2.pddl)
expect_run(11 "the time limit was reached before a plan was found (" ${ALPLAN} plan --time-limit 0.3 ${train}/domain.pddl ${train}/instances/instance-2.pddl)
expect_stdout(0 "\"best_index\": 1.*\"schema_version\": 1" ${ALPLAN} plan --json ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)

# A classical task: a sequential plan and its cost, no timestamps.
expect_stdout(0 "\n\\(switch-a\\)\n\\(switch-b\\)\n; cost = 2 \\(unit cost\\)\n"
  ${ALPLAN} plan ${data}/switches-domain.pddl ${data}/switches-problem.pddl --out ${WORK}/switches.plan)
file(READ ${WORK}/switches.plan written)
if(NOT written STREQUAL "(switch-a)\n(switch-b)\n; cost = 2 (unit cost)\n")
  message(FATAL_ERROR "--out wrote '${written}'")
endif()
expect_run(0 "Plan valid." ${ALPLAN} validate ${data}/switches-domain.pddl ${data}/switches-problem.pddl
  ${WORK}/switches.plan)
expect_stdout(0 "\"format\": \"sequential\"" ${ALPLAN} plan --json ${data}/switches-domain.pddl
  ${data}/switches-problem.pddl)
# A temporal task keeps its timestamps.
expect_stdout(0 "\"format\": \"temporal\"" ${ALPLAN} plan --json ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)

# The header names the engine and its heuristic, the weight as written, and
# seconds to the millisecond.
expect_stdout(0 "; plan found after [0-9]+\\.[0-9][0-9][0-9] s by wastar \\(w=2\\) with lmcut"
  ${ALPLAN} plan --search "wastar(lmcut, w=2)" ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)

# --diverse prints the same schema, with what it adds.
expect_stdout(0 "\"best_index\": null.*\"diagnostics\": \\[.*\"distances\".*\"limit\": null.*\"planner_calls\".*\"schema_version\": 1.*\"seconds\": {.*\"statistics\": {"
  ${ALPLAN} plan --diverse 2 --json ${DATA}/planner/cups-domain.pddl ${DATA}/planner/cups-problem.pddl)
# A warning about the input is in the JSON of a solved run too.
file(WRITE ${WORK}/undeclared-domain.pddl "(define (domain undeclared) (:requirements :strips)
  (:predicates (a) (b)) (:action x :parameters () :precondition (not (a)) :effect (b)))")
file(WRITE ${WORK}/undeclared-problem.pddl "(define (problem p) (:domain undeclared) (:init) (:goal (b)))")
expect_stdout(0 "\"diagnostics\": \\[\n[^]]*warning[^]]*negative-preconditions.*\"status\": \"solved\""
  ${ALPLAN} plan --json ${WORK}/undeclared-domain.pddl ${WORK}/undeclared-problem.pddl)

# `validate --json` too: an object on stdout for bad input.
expect_stdout(2 "no-such-plan.*\"status\": \"input_error\".*\"valid\": null"
  ${ALPLAN} validate --json ${DATA}/planner/switches-domain.pddl ${DATA}/planner/switches-problem.pddl ${WORK}/no-such-plan)
expect_stdout(0 "\"status\": \"valid\"" ${ALPLAN} validate --json ${DATA}/planner/switches-domain.pddl
  ${DATA}/planner/switches-problem.pddl ${WORK}/switches.plan)
