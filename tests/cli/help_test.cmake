# Each subcommand's help shows defaults, required options and every accepted
# name (issue 46). Variables: ALPLAN.
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "--time-limit FLOAT:NONNEGATIVE=60" ${ALPLAN} plan --help)
expect_run(0 "--homes INT:POSITIVE=40" ${ALPLAN} bench repair --help)
expect_run(0 "(required)" ${ALPLAN} bench repair --help)
expect_run(0 "shared/benchmarks/ipc; required" ${ALPLAN} bench stability --help)
expect_run(0 "--seniors INT:INT in [1 - 1000]=40" ${ALPLAN} bench home --help)
expect_run(0 "adapt, stable, switch" ${ALPLAN} scenario --help)
expect_run(0 "default, anytime, ehc, gbfs, wastar, complete, pddl3" ${ALPLAN} plan --help)
