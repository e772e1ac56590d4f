# `alplan scenario` as users run it. Variables: ALPLAN, SHARED, DATA, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "a1  : 140.008 : (carry robot1 mug_id01 kitchen1)" ${ALPLAN} scenario paper-1)
expect_run(0 "a6  : 260.016 : (cheer_received senior1 clarinet_id01)" ${ALPLAN} scenario paper-2)
expect_run(0 "a2  : 5.002   : (entertainment2_suggested senior1 tv_id01)" ${ALPLAN} scenario paper-3)
expect_run(0 "\"goal_reached\": true" ${ALPLAN} scenario paper-1 --json --strategy patch)
expect_run(1 "no repair" ${ALPLAN} scenario paper-1 --strategy suggest)
# A failed repair is explained in three parts, in text and in JSON.
foreach(part "Failed repair (suggest):" "Why: senior1 is stressed and terrified"
        "What went wrong: at 140.008, (available glass_id05)" "Why it could not be repaired: no activity")
  expect_run(1 "${part}" ${ALPLAN} scenario paper-1 --strategy suggest)
endforeach()
expect_run(1 "\"why\": \"senior1 is stressed and terrified" ${ALPLAN} scenario paper-1 --strategy suggest --json)
expect_run(2 "unknown scenario 'paper-4'" ${ALPLAN} scenario paper-4)
expect_run(2 "unknown repair strategy 'pray'" ${ALPLAN} scenario paper-1 --strategy pray)
expect_run(2 "cannot open" ${ALPLAN} scenario paper-1 --domains-dir ${WORK}/nowhere)
# The observation models: the camera alone meets the failure on arrival,
# and an unknown model is refused.
expect_run(0 "a1  : 140.008 : (carry robot1 mug_id01 kitchen1)" ${ALPLAN} scenario paper-1 --observe camera)
expect_run(1 "No repair yet (replan)" ${ALPLAN} scenario paper-1 --strategy replan --observe iot)
expect_run(2 "--observe takes full, iot or camera" ${ALPLAN} scenario paper-1 --observe psychic)
