# `alplan ground`, `alplan validate` and `alplan bench grounding` as users run
# them. Variables: ALPLAN, SHARED, DATA, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

set(ipc ${SHARED}/benchmarks/ipc)
set(plans ${SHARED}/benchmarks/plans)
set(depots ${ipc}/ipc-2002/depots-time-simple-automatic)

expect_run(0 "actions: 129 (129 durative, 0 instantaneous)" ${ALPLAN} ground
  ${ipc}/ipc-2002/zenotravel-time-simple-automatic/domain.pddl
  ${ipc}/ipc-2002/zenotravel-time-simple-automatic/instances/instance-1.pddl)
expect_run(0 "time: normalize" ${ALPLAN} ground ${depots}/domain.pddl ${depots}/instances/instance-1.pddl)
expect_run(0 "\"axiom_strata\"" ${ALPLAN} ground --json
  ${ipc}/ipc-2004/psr-middle-derived-predicates-adl/domain.pddl
  ${ipc}/ipc-2004/psr-middle-derived-predicates-adl/instances/instance-1.pddl)
expect_run(0 "durative-action (board person1 plane1 city0)" ${ALPLAN} ground --dump
  ${ipc}/ipc-2002/zenotravel-time-simple-automatic/domain.pddl
  ${ipc}/ipc-2002/zenotravel-time-simple-automatic/instances/instance-1.pddl)
expect_run(2 "undefined predicate 'senty_image'" ${ALPLAN} ground
  ${ipc}/ipc-2004/satellite-time-time-windows-strips/domain.pddl
  ${ipc}/ipc-2004/satellite-time-time-windows-strips/instances/instance-31.pddl)

expect_run(0 "Plan valid. Makespan: 27.001. Metric: 27.001." ${ALPLAN} validate
  ${depots}/domain.pddl ${depots}/instances/instance-1.pddl
  ${plans}/ipc-2002/depots-time-simple-automatic/instance-1.optic.plan)
expect_run(1 "Invariant for (load hoist1 crate0 truck0 distributor0) has its condition unsatisfied between time 8.501 to 10"
  ${ALPLAN} validate ${depots}/domain.pddl ${depots}/instances/instance-1.pddl
  ${plans}/ipc-2002/depots-time-simple-automatic/instance-1.optic.shift-half-duration.plan)
expect_run(1 "\"kind\": \"unknown_action\"" ${ALPLAN} validate --json
  ${depots}/domain.pddl ${depots}/instances/instance-1.pddl
  ${plans}/ipc-2002/depots-time-simple-automatic/instance-1.optic.unknown-action.plan)
expect_run(1 "has an unsatisfied precondition at time 0.001" ${ALPLAN} validate --epsilon 0.001
  ${depots}/domain.pddl ${depots}/instances/instance-1.pddl
  ${plans}/ipc-2002/depots-time-simple-automatic/instance-1.optic.same-start.plan)

file(WRITE ${WORK}/broken.plan "0.000: (lift hoist0 crate1 pallet0 depot0) [1.000]\n1.0 (drive truck0 a b)\n")
expect_run(2 "broken.plan:2:5: error: expected ':' after the time of a plan step" ${ALPLAN} validate
  ${depots}/domain.pddl ${depots}/instances/instance-1.pddl ${WORK}/broken.plan)
expect_run(2 "cannot open the file" ${ALPLAN} validate ${depots}/domain.pddl ${depots}/instances/instance-1.pddl
  ${WORK}/missing.plan)

file(WRITE ${WORK}/suite.list "${depots}/domain.pddl ${depots}/instances/instance-1.pddl\n")
expect_run(0 "1 of 1 problems grounded within 60 s" ${ALPLAN} bench grounding --suite ${WORK}/suite.list
  --out ${WORK}/bench)
if(NOT EXISTS ${WORK}/bench/grounding.json OR NOT EXISTS ${WORK}/bench/grounding.csv)
  message(FATAL_ERROR "bench grounding did not write its files")
endif()
