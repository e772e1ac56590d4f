# `alplan gen home` and `alplan bench repair` as users run them.
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "(:domain assisted_living)" ${ALPLAN} gen home --rooms 6 --seniors 3 --objects 10 --seed 4)
expect_run(0 "wrote" ${ALPLAN} gen home --rooms 6 --seniors 3 --objects 10 --seed 4 --out ${WORK}/home.pddl)
expect_run(0 "; plan found" ${ALPLAN} plan ${CMAKE_CURRENT_LIST_DIR}/../../domains/assisted_living/domain.pddl
  ${WORK}/home.pddl)
expect_run(2 "at least 4 rooms" ${ALPLAN} gen home --rooms 3)
expect_run(0 "--scatter 0.5" ${ALPLAN} gen home --rooms 6 --seniors 3 --objects 10 --seed 4 --scatter 0.5)
expect_run(2 "--scatter must be within 0..1" ${ALPLAN} gen home --scatter 1.5)
expect_run(2 "--scatter must be within 0..1" ${ALPLAN} bench repair --homes 1 --scatter -0.1 --recognizer simulated
  --out ${WORK}/repair-bad-scatter)
expect_run(0 "latency median ms" ${ALPLAN} bench repair --homes 2 --runs-per-home 2 --seed 3
  --strategies replan,patch,suggest --external --recognizer simulated --out ${WORK}/repair)
foreach(f runs.csv runs.json summary.md summary.json plots/success-rate.svg plots/stability-vs-replan.svg
        plots/delay-vs-replan.svg)
  if(NOT EXISTS ${WORK}/repair/${f})
    message(FATAL_ERROR "bench repair did not write ${f}")
  endif()
endforeach()
# A run that never comforts the senior has no delay (not zero, not negative;
# a comforted run's delay may be negative: a suggestion can comfort sooner
# than the planned carry would have, at the suggestion's cost):
# columns are home,run,kind,strategy,comforted,repairs,latency_ms,
# perception_ms,stability,planner_calls,delay,...; suggest fails where the
# senior is terrified.
file(STRINGS ${WORK}/repair/runs.csv rows)
set(failed 0)
foreach(row IN LISTS rows)
  if(row MATCHES "^[^,]*,[^,]*,[^,]*,[^,]*,no,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*,([^,]*),")
    math(EXPR failed "${failed} + 1")
    if(NOT "${CMAKE_MATCH_1}" STREQUAL "")
      message(FATAL_ERROR "a run that never comforted the senior has delay '${CMAKE_MATCH_1}': ${row}")
    endif()
  endif()
endforeach()
if(failed EQUAL 0)
  message(FATAL_ERROR "expected a failed run (suggest) in ${WORK}/repair/runs.csv")
endif()
# The repairs reuse the grounding made at the start; without it, none does.
expect_run(0 "grounding reused" ${ALPLAN} bench repair --homes 2 --runs-per-home 1 --seed 3 --strategies replan
  --recognizer simulated --out ${WORK}/repair-reuse)
expect_run(0 "grounding reused" ${ALPLAN} bench repair --homes 2 --runs-per-home 1 --seed 3 --strategies replan
  --recognizer simulated --no-grounding-reuse --out ${WORK}/repair-no-reuse)
foreach(pair "repair-reuse;some" "repair-no-reuse;0")
  list(GET pair 0 dir)
  list(GET pair 1 reused)
  file(READ ${WORK}/${dir}/summary.json summary)
  string(REGEX MATCH "\"repairs_reusing_grounding\": ([0-9]+)" found "${summary}")
  set(count "${CMAKE_MATCH_1}")
  set(at 0)
  if("${count}" STREQUAL "" OR ("${reused}" STREQUAL "0" AND NOT count EQUAL 0)
     OR ("${reused}" STREQUAL "some" AND count EQUAL 0))
    set(at -1)
  endif()
  if(at EQUAL -1)
    message(FATAL_ERROR "${dir}: expected ${reused} repairs reusing the grounding in ${summary}")
  endif()
endforeach()
expect_run(2 "unknown repair strategy 'fast'" ${ALPLAN} bench repair --homes 1 --strategies fast --out ${WORK}/x)
# Failures of every kind the world simulator draws, emotion changes included.
expect_run(0 "latency median ms" ${ALPLAN} bench repair --homes 1 --runs-per-home 2 --seed 2 --strategies replan
  --recognizer simulated --events all --out ${WORK}/repair-all)
expect_run(0 "latency median ms" ${ALPLAN} bench repair --homes 1 --runs-per-home 1 --seed 2 --strategies replan
  --recognizer simulated --events emotion --out ${WORK}/repair-emotion)
file(READ ${WORK}/repair-emotion/runs.csv emotion_runs)
if(NOT emotion_runs MATCHES "senior1 is no longer sad but bored")
  message(FATAL_ERROR "bench repair --events emotion drew no emotion change:\n${emotion_runs}")
endif()
expect_run(2 "--events takes" ${ALPLAN} bench repair --homes 1 --events earthquake --out ${WORK}/x)
# The study's camera: the paper's CNN names what the simulator made, and
# substitute's latency includes it; an unknown recognizer or observation
# model is refused.
expect_run(0 "classifier_test_accuracy" ${ALPLAN} bench repair --homes 2 --runs-per-home 2 --seed 1
  --strategies replan,substitute --events sibling --no-paper-home --out ${WORK}/repair-cnn)
expect_run(2 "--recognizer takes cnn or simulated" ${ALPLAN} bench repair --homes 1 --recognizer oracle --out ${WORK}/x)
expect_run(2 "--observe takes full, iot or camera" ${ALPLAN} bench repair --homes 1 --observe psychic --out ${WORK}/x)
# The camera alone: a senior who moved is searched for, room by room, and
# found; with --no-search the robot knows only that they left.
expect_run(0 "latency median ms" ${ALPLAN} bench repair --homes 1 --runs-per-home 2 --seed 3 --strategies replan
  --recognizer simulated --events moves --observe camera --no-paper-home --out ${WORK}/repair-search)
file(READ ${WORK}/repair-search/runs.json searched)
if(NOT searched MATCHES "\"comforted\": true" OR NOT searched MATCHES "\"search_steps\": [1-9]")
  message(FATAL_ERROR "bench repair --observe camera: no senior who moved was searched for and found:\n${searched}")
endif()
expect_run(0 "not searched for (--no-search)" ${ALPLAN} bench repair --homes 1 --runs-per-home 2 --seed 3
  --strategies replan --recognizer simulated --events moves --observe camera --no-paper-home --no-search
  --out ${WORK}/repair-no-search)
file(READ ${WORK}/repair-no-search/runs.json unsearched)
if(unsearched MATCHES "\"comforted\": true" OR unsearched MATCHES "\"search_steps\": [1-9]")
  message(FATAL_ERROR "bench repair --no-search: a senior who moved was searched for or found:\n${unsearched}")
endif()
# Under two models: each in its folder, observation.md pairing them; its
# tables written again from the runs alone are the same tables.
expect_run(0 "iot minus camera (what the tags are worth)" ${ALPLAN} bench repair --homes 2 --runs-per-home 1 --seed 3
  --strategies replan,patch --recognizer simulated --observe iot,camera --scatter 0.5 --no-paper-home
  --out ${WORK}/repair-models)
file(READ ${WORK}/repair-models/observation.md first_tables)
file(READ ${WORK}/repair-models/iot/summary.md first_summary)
file(REMOVE ${WORK}/repair-models/observation.md)
file(WRITE ${WORK}/repair-models/iot/summary.md "stale\n## Per failure kind and strategy\nstale tables\n")
expect_run(0 "wrote" ${ALPLAN} bench repair --summarize ${WORK}/repair-models)
file(READ ${WORK}/repair-models/observation.md again)
if(NOT first_tables STREQUAL again)
  message(FATAL_ERROR "bench repair --summarize wrote other tables than the run did")
endif()
# A model's summary.md: its head kept, its tables written again from runs.json.
file(READ ${WORK}/repair-models/iot/summary.md summary_again)
string(FIND "${first_summary}" "## Per failure kind and strategy" tables_at)
string(SUBSTRING "${first_summary}" ${tables_at} -1 first_summary_tables)
if(NOT summary_again STREQUAL "stale\n${first_summary_tables}")
  message(FATAL_ERROR "bench repair --summarize wrote other summary tables than the run did")
endif()
expect_run(2 "no full/, iot/ or camera/ runs.json" ${ALPLAN} bench repair --summarize ${WORK}/repair)
file(WRITE ${WORK}/repair-models/camera/runs.json "[{\"home\": 1}]")
expect_run(2 "repair-models/camera/runs.json: " ${ALPLAN} bench repair --summarize ${WORK}/repair-models)
# Homes of seeds 1001-2000 are held out (test_set_ledger.h): a run touching
# one without --reason is refused before it runs.
expect_run(2 "held-out homes (seeds 1001-2000)" ${ALPLAN} bench repair --homes 2 --seed 1000 --strategies replan
  --recognizer simulated --no-paper-home --out ${WORK}/held-out)
if(EXISTS ${WORK}/held-out)
  message(FATAL_ERROR "bench repair ran on held-out homes it refused")
endif()
# The stability testbed on an IPC domain (benchmarks/harness/stability_bench.h):
# a small run writes its files; bad flags are refused with the reason.
expect_run(0 "Plan stability" ${ALPLAN} bench stability --ipc ${SHARED}/benchmarks/ipc --domains rovers --problems 1
  --perturbations 1 --kinds fact --strategies replan,adapt --out ${WORK}/stability)
foreach(f runs.csv runs.json summary.md)
  if(NOT EXISTS ${WORK}/stability/${f})
    message(FATAL_ERROR "bench stability did not write ${f}")
  endif()
endforeach()
# A wrong --ipc folder skips every problem: exit 2, not a study of nothing.
expect_run(2 "no perturbation was run" ${ALPLAN} bench stability --ipc ${WORK}/no-such-suite --domains rovers --problems 1
  --perturbations 1 --kinds fact --strategies replan --out ${WORK}/stability-nothing)
expect_run(2 "--problems takes N or N-M" ${ALPLAN} bench stability --ipc ${SHARED}/benchmarks/ipc --problems x
  --out ${WORK}/x)
expect_run(2 "--kinds takes fact, object, goal; got 'meteor'" ${ALPLAN} bench stability --ipc ${SHARED}/benchmarks/ipc
  --kinds meteor --out ${WORK}/x)
expect_run(2 "unknown repair strategy 'fast'" ${ALPLAN} bench stability --ipc ${SHARED}/benchmarks/ipc
  --strategies replan,fast --out ${WORK}/x)
expect_run(2 "--stable-search: search configuration" ${ALPLAN} bench stability --ipc ${SHARED}/benchmarks/ipc
  --stable-search "wastar(" --out ${WORK}/x)
expect_run(2 "--stable-search must be a complete search" ${ALPLAN} bench stability --ipc ${SHARED}/benchmarks/ipc
  --stable-search "wastar(lmcut, w=1, order=metric)" --out ${WORK}/x)
# bench planners on a domain of a suite (--domains), one problem: its row,
# and a prefix no domain has is refused.
expect_run(0 "trucks-preferences-complex" ${ALPLAN} bench planners --suite ${SHARED}/benchmarks/pddl3
  --domains ipc-2006/trucks-preferences-complex --first 1 --time-limit 10 --out ${WORK}/planners)
file(STRINGS ${WORK}/planners/runs.csv planner_rows)
list(LENGTH planner_rows planner_row_count)
if(NOT planner_row_count EQUAL 2)
  message(FATAL_ERROR "bench planners --domains --first 1 wrote ${planner_row_count} lines, not a head and one run")
endif()
expect_run(2 "--domains: no domain of the suite begins with any of them" ${ALPLAN} bench planners
  --suite ${SHARED}/benchmarks/pddl3 --domains no-such/ --out ${WORK}/planners-none)
