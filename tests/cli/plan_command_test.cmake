# `alplan plan` as users run it: exit codes 0 (plan), 10 (proven
# unsolvable), 11 (limits reached), 2 (input error or unsupported input).
# Variables: ALPLAN, SHARED, DATA, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

set(ipc ${SHARED}/benchmarks/ipc)
set(zeno ${ipc}/ipc-2002/zenotravel-time-simple-automatic)
set(floor ${ipc}/ipc-2011/floor-tile-temporal-satisficing)
set(data ${DATA}/planner)

expect_run(0 "; plan found" ${ALPLAN} plan ${zeno}/domain.pddl ${zeno}/instances/instance-1.pddl
  --out ${WORK}/zeno-1.plan)
expect_run(0 "Plan valid." ${ALPLAN} validate ${zeno}/domain.pddl ${zeno}/instances/instance-1.pddl ${WORK}/zeno-1.plan)
expect_run(0 "\"expanded\"" ${ALPLAN} plan --json ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)
expect_run(0 "(refuel a)" ${ALPLAN} plan --anytime --time-limit 5 ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)
expect_run(0 "\"status\": \"solved\"" ${ALPLAN} plan --json --search wastar --weight 2
  ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)
expect_run(10 "the goal can never hold ((at island))" ${ALPLAN} plan ${data}/mixed-domain.pddl
  ${data}/mixed-unreachable.pddl)
expect_run(11 "limit" ${ALPLAN} plan --time-limit 0.3 ${floor}/domain.pddl ${floor}/instances/instance-5.pddl)
expect_run(2 "#t" ${ALPLAN} plan ${data}/tank-continuous.pddl ${data}/tank-problem.pddl)
expect_run(2 "no-such-file.pddl" ${ALPLAN} plan ${data}/no-such-file.pddl ${data}/tank-problem.pddl)
expect_run(2 "search" ${ALPLAN} plan --search dfs ${data}/mixed-domain.pddl ${data}/mixed-problem.pddl)
