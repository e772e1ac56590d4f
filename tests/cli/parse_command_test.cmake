# Runs `alplan parse` as a user would and checks exit codes and output.
# Variables: ALPLAN (the executable), SHARED (../shared), DATA (tests/data).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

set(zeno ${SHARED}/benchmarks/ipc/ipc-2002/zenotravel-time-simple-automatic)
expect_run(0 "durative actions: 5" ${ALPLAN} parse ${zeno}/domain.pddl ${zeno}/instances/instance-1.pddl)
expect_run(0 "metric: minimize (total-time)" ${ALPLAN} parse ${zeno}/domain.pddl ${zeno}/instances/instance-1.pddl)
expect_run(0 "\"durative_actions\": 5" ${ALPLAN} parse --json ${zeno}/domain.pddl ${zeno}/instances/instance-1.pddl)
expect_run(0 "(:durative-action fly" ${ALPLAN} parse --print ${zeno}/domain.pddl)
expect_run(2 "as_printed.pddl:82:44: error: expected :parameters" ${ALPLAN} parse ${DATA}/paper_fig2/as_printed.pddl)
expect_run(2 "no-such-file.pddl: error: cannot open the file: No such file or directory" ${ALPLAN} parse no-such-file.pddl)
expect_run(2 "error: expected a problem definition, found 'domain'" ${ALPLAN} parse ${zeno}/domain.pddl ${zeno}/domain.pddl)
expect_run(2 "" ${ALPLAN} parse)
expect_run(2 "" ${ALPLAN} parse --no-such-flag ${zeno}/domain.pddl)
expect_run(2 "" ${ALPLAN} no-such-command)

# --print writes PDDL that parses back to the same summary.
execute_process(COMMAND ${ALPLAN} parse --print ${DATA}/constructs/domain.pddl OUTPUT_FILE ${CMAKE_CURRENT_BINARY_DIR}/printed_domain.pddl RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "parse --print failed")
endif()
expect_run(0 "derived predicates: 2" ${ALPLAN} parse ${CMAKE_CURRENT_BINARY_DIR}/printed_domain.pddl)
