# `alplan perceive` as users run it (through the perception module).
# Variables: ALPLAN, SHARED, DATA, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)
set(SKIMAGE /usr/lib/python3/dist-packages/skimage/data)

# Emotions: the smiling astronaut, and what an emotion means for goals.
expect_run(0 "face 1 at (177, 67) 93x93: happy" ${ALPLAN} perceive emotion ${SKIMAGE}/astronaut.png)
expect_run(0 "no bored class" ${ALPLAN} perceive emotion ${SKIMAGE}/astronaut.png)
expect_run(0 "\"label\": \"happy\"" ${ALPLAN} perceive emotion ${SKIMAGE}/astronaut.png --json)
expect_run(0 ": 0 faces" ${ALPLAN} perceive emotion ${SKIMAGE}/coffee.png)
expect_run(2 "no such file" ${ALPLAN} perceive emotion ${WORK}/missing.png)
expect_run(2 "an IMAGE is required" ${ALPLAN} perceive emotion)
file(WRITE ${WORK}/not-an-image.png "this is text")
expect_run(2 "cannot read an image" ${ALPLAN} perceive emotion ${WORK}/not-an-image.png)

# Objects: a real photo of a cup is a drinking vessel.
expect_run(0 "cup (drinking_vessel)" ${ALPLAN} perceive objects ${SKIMAGE}/coffee.png)
expect_run(0 "\"supertype\": \"drinking_vessel\"" ${ALPLAN} perceive objects ${SKIMAGE}/coffee.png --json)
expect_run(2 "not a model file" ${ALPLAN} perceive objects ${SKIMAGE}/coffee.png --classifier ${WORK}/not-an-image.png)

# The ontology from WordNet: supertype -> subtypes, augmented ones marked.
expect_run(0 "drinking_vessel -> drinking_glass, glass_bottle, +cup, +mug" ${ALPLAN} perceive ontology)
expect_run(0 "making_music -> guitar, violin, +drum, +clarinet" ${ALPLAN} perceive ontology)
expect_run(0 "anchored at musical_instrument.n.01" ${ALPLAN} perceive ontology --explain)
expect_run(0 "wrote ${WORK}/augmented.ttl" ${ALPLAN} perceive ontology --out ${WORK}/augmented.ttl)
file(READ ${WORK}/augmented.ttl turtle)
string(FIND "${turtle}" "al:mug a owl:Class ; rdfs:subClassOf al:drinking_vessel ; al:augmented true" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the written ontology lacks the augmented mug:\n${turtle}")
endif()
expect_run(2 "cannot read the category configuration" ${ALPLAN} perceive ontology --config ${WORK}/nowhere.txt)

# Stress: the paper's protocol on the simulated database, then on CSV files.
expect_run(0 "Table 1 form" ${ALPLAN} perceive stress --evaluate --subjects 20 --duration 100 --k 2,4)
expect_run(0 "| Real | Stressed |" ${ALPLAN} perceive stress --evaluate --subjects 20 --duration 100 --k 2,4)
expect_run(0 "wrote 12 subjects" ${ALPLAN} perceive stress simulate --out ${WORK}/ppg --subjects 12 --duration 80)
expect_run(0 "saved to ${WORK}/stress.yml" ${ALPLAN} perceive stress train --data ${WORK}/ppg --out ${WORK}/stress.yml --k 2,3)
expect_run(0 "accuracy" ${ALPLAN} perceive stress evaluate --model ${WORK}/stress.yml --data ${WORK}/ppg)
file(GLOB recordings ${WORK}/ppg/s01/*.csv)
list(GET recordings 0 one)
expect_run(0 "HR" ${ALPLAN} perceive stress detect --model ${WORK}/stress.yml ${one})
expect_run(2 "needs --evaluate or a subcommand" ${ALPLAN} perceive stress)
expect_run(0 "| paper, own baseline (first 24 readings, fixed) | 0 / 4 |" ${ALPLAN} perceive stress false-alarms
  --seniors 4 --minutes 6 --onset 3)
expect_run(0 "\"false_alarm_rate\"" ${ALPLAN} perceive stress false-alarms --seniors 2 --minutes 4 --onset 3 --json)
expect_run(2 "onset must lie inside" ${ALPLAN} perceive stress false-alarms --minutes 4 --onset 5)
file(WRITE ${WORK}/bad/s1.csv "time,ppg,label\n0,0.1,1\n0.02,abc,1\n")
expect_run(2 "s1.csv:3:6: error: column 2 (ppg)" ${ALPLAN} perceive stress train --data ${WORK}/bad --out ${WORK}/x.yml)

# Learning objects from generated images; a trained model is saved and used.
expect_run(0 "test accuracy" ${ALPLAN} perceive objects train --layout generated --limit 360 --epochs 2
           --out ${WORK}/objects.pt)
expect_run(0 "accuracy" ${ALPLAN} perceive objects evaluate --model ${WORK}/objects.pt --layout generated --limit 180)
expect_run(0 "[coco:cup]" ${ALPLAN} perceive objects ${SKIMAGE}/coffee.png --classifier ${WORK}/objects.pt)
expect_run(2 "--data is required" ${ALPLAN} perceive emotion train --layout kdef)
expect_run(2 "no KDEF images" ${ALPLAN} perceive emotion train --data ${WORK}/ppg)
