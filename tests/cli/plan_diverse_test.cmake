# `alplan plan --diverse K` (issue 32): K plans, each headed "; plan i of
# K", then their pairwise distances; fewer when no more are found, said so.
# Variables: ALPLAN, SHARED, DATA, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

set(data ${DATA}/planner)
execute_process(COMMAND ${ALPLAN} plan --diverse 3 ${data}/cups-domain.pddl ${data}/cups-problem.pddl
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
foreach(expected "; plan 1 of 3" "; plan 2 of 3" "; plan 3 of 3" "(serve c1)" "(serve c2)" "(serve c3)"
        "; distances (ground actions added + removed):\n; 0 2 2\n; 2 0 2\n; 2 2 0\n")
  string(FIND "${out}" "${expected}" at)
  if(NOT code EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "plan --diverse 3 (exit ${code}) lacks '${expected}':\n${out}${err}")
  endif()
endforeach()
expect_run(0 "; found 3 of 5 plans at least 2 actions apart (no more" ${ALPLAN} plan --diverse 5
  ${data}/cups-domain.pddl ${data}/cups-problem.pddl)
expect_run(0 "\"distances\"" ${ALPLAN} plan --diverse 2 --min-distance 2 --json
  ${data}/cups-domain.pddl ${data}/cups-problem.pddl)
# Without a plan, the exit code the plan command gives: 10, proven unsolvable.
expect_run(10 "; status: unsolvable" ${ALPLAN} plan --diverse 3 ${data}/mixed-domain.pddl ${data}/mixed-unreachable.pddl)
# --min-distance means nothing without --diverse.
expect_run(2 "--diverse" ${ALPLAN} plan --min-distance 3 ${data}/cups-domain.pddl ${data}/cups-problem.pddl)
