# `alplan gen home` and `alplan bench repair` as users run them.
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "(:domain assisted_living)" ${ALPLAN} gen home --rooms 6 --seniors 3 --objects 10 --seed 4)
expect_run(0 "wrote" ${ALPLAN} gen home --rooms 6 --seniors 3 --objects 10 --seed 4 --out ${WORK}/home.pddl)
expect_run(0 "; plan found" ${ALPLAN} plan ${CMAKE_CURRENT_LIST_DIR}/../../domains/assisted_living/domain.pddl
  ${WORK}/home.pddl)
expect_run(2 "at least 4 rooms" ${ALPLAN} gen home --rooms 3)
expect_run(0 "latency median ms" ${ALPLAN} bench repair --homes 2 --runs-per-home 1 --seed 3
  --strategies replan,patch --external --out ${WORK}/repair)
foreach(f runs.csv runs.json summary.md summary.json plots/latency-median-ms.svg plots/stability.svg)
  if(NOT EXISTS ${WORK}/repair/${f})
    message(FATAL_ERROR "bench repair did not write ${f}")
  endif()
endforeach()
expect_run(2 "unknown repair strategy 'fast'" ${ALPLAN} bench repair --homes 1 --strategies fast --out ${WORK}/x)
