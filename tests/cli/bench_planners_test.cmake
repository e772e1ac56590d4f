# `bench planners` as a small Downward Lab (issue 46): another planner by its
# command line beside ours, its plans judged by our validator, each plan
# named beside its problem in runs.csv, scores explained, where the results
# went said, and a warning when our limit differs from the baseline's.
# Variables: ALPLAN, SHARED, DATA, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

set(suite ${DATA}/bench-suite)
file(REMOVE_RECURSE ${WORK}/bench)
expect_run(0 "results: ${WORK}/bench/" ${ALPLAN} bench planners --suite ${suite} --time-limit 10 --out ${WORK}/bench
  "--planner=scripted=sh ${suite}/scripted-planner.sh {domain} {problem} {plan}")
file(READ ${WORK}/bench/runs.csv runs)
# Ours solves both; the scripted planner's plan is valid for instance 1 only.
if(NOT runs MATCHES "instance-1.pddl,solved,[^\n]*plans/0.plan,solved,[^\n]*plans/0.scripted.plan")
  message(FATAL_ERROR "runs.csv: ${runs}")
endif()
if(NOT runs MATCHES "instance-2.pddl,solved,[^\n]*plans/1.plan,invalid,")
  message(FATAL_ERROR "runs.csv: ${runs}")
endif()
file(READ ${WORK}/bench/summary.md summary)
if(NOT summary MATCHES "coverage ours \\| scripted \\|" OR NOT summary MATCHES "\\| switches \\| 2/2 \\| 1/2 \\|")
  message(FATAL_ERROR "summary.md: ${summary}")
endif()
if(summary MATCHES "OPTIC")
  message(FATAL_ERROR "without --baseline no OPTIC column: ${summary}")
endif()
if(NOT EXISTS ${WORK}/bench/plans/0.scripted.plan)
  message(FATAL_ERROR "the other planner's plan was not kept")
endif()
expect_run(0 "scores (IPC 2008-2014)" ${ALPLAN} bench planners --suite ${suite} --time-limit 10 --out ${WORK}/bench)

# An anytime planner stopped by the limit after writing its plan: the plan counts.
expect_run(0 "anytime: solved value 2" ${ALPLAN} bench planners --suite ${suite} --first 1 --time-limit 1
  --out ${WORK}/bench-anytime "--planner=anytime=sh ${suite}/anytime-planner.sh {domain} {problem} {plan}")

# Limits unlike the baseline's are said, not compared silently.
expect_run(0 "warning: our runs have a 2 s limit, the baseline's 60 s" ${ALPLAN} bench planners --suite ${suite}
  --baseline ${SHARED}/benchmarks/baseline --time-limit 2 --out ${WORK}/bench-short)
# A planner given without its placeholders is refused.
expect_run(2 "has no {plan}" ${ALPLAN} bench planners --suite ${suite} --planner "x=true {domain} {problem}")
