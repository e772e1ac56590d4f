# `alplan validate` standing in for VAL's Validate: its -t and -v, "-" for
# standard input, every violation listed, clear file errors. Variables:
# ALPLAN, SHARED, DATA, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

# Two rooms and a lamp in each; light needs the robot there.
file(WRITE ${WORK}/domain.pddl "(define (domain lamps)
  (:requirements :strips :typing)
  (:types room)
  (:predicates (at ?r - room) (lit ?r - room) (door ?a ?b - room))
  (:action go :parameters (?a ?b - room) :precondition (and (at ?a) (door ?a ?b))
    :effect (and (not (at ?a)) (at ?b)))
  (:action light :parameters (?r - room) :precondition (at ?r) :effect (lit ?r)))
")
file(WRITE ${WORK}/problem.pddl "(define (problem two) (:domain lamps)
  (:objects hall kitchen - room)
  (:init (at hall) (door hall kitchen) (door kitchen hall))
  (:goal (and (lit hall) (lit kitchen))))
")
file(WRITE ${WORK}/good.plan "(light hall)\n(go hall kitchen)\n(light kitchen)\n")
# Two independent mistakes: the kitchen is lit from the hall, and the robot
# then goes from a room it is not in; the hall lamp is never lit.
file(WRITE ${WORK}/bad.plan "(light kitchen)\n(go kitchen hall)\n")
set(task ${WORK}/domain.pddl ${WORK}/problem.pddl)

# VAL's flags: -t is the tolerance (epsilon), -v a state trace per happening.
expect_run(0 "Plan valid. Makespan: 3." ${ALPLAN} validate -t 0.01 ${task} ${WORK}/good.plan)
expect_run(0 "Happening 2, time 2:\n  (go hall kitchen)\n  deletes (at hall)\n  adds (at kitchen)\n"
  ${ALPLAN} validate -v ${task} ${WORK}/good.plan)
expect_run(1 "Happening 1, time 1:\n  (light kitchen)\n  adds (lit kitchen)\n  violation: "
  ${ALPLAN} validate -v ${task} ${WORK}/bad.plan)

# Every violation: the first as before, then the rest.
expect_run(1 "Plan invalid. (light kitchen) has an unsatisfied precondition at time 1" ${ALPLAN} validate
  ${task} ${WORK}/bad.plan)
expect_run(1 "2 more violations, found going on with the effects applied" ${ALPLAN} validate ${task} ${WORK}/bad.plan)
expect_run(1 "(go kitchen hall) has an unsatisfied precondition at time 2" ${ALPLAN} validate ${task}
  ${WORK}/bad.plan)
expect_run(1 "\"violations\": [" ${ALPLAN} validate --json ${task} ${WORK}/bad.plan)

# Standard input for the plan, or for the domain; not for two files.
expect_run_input(0 "Plan valid." ${WORK}/good.plan ${ALPLAN} validate ${task} -)
expect_run_input(0 "Plan valid." ${WORK}/domain.pddl ${ALPLAN} validate - ${WORK}/problem.pddl ${WORK}/good.plan)
expect_run_input(2 "standard input ('-') is given for more than one file" ${WORK}/good.plan
  ${ALPLAN} validate ${WORK}/domain.pddl - -)
file(WRITE ${WORK}/broken.plan "(light hall\n")
expect_run_input(2 "<stdin>:" ${WORK}/broken.plan ${ALPLAN} validate ${task} -)

# A missing file: its path and the reason, no "0:0".
expect_run(2 "${WORK}/missing.plan: error: cannot open the file: No such file or directory" ${ALPLAN} validate
  ${task} ${WORK}/missing.plan)
expect_run(2 "${WORK}/missing.pddl: error: cannot open the file: No such file or directory" ${ALPLAN} validate
  ${WORK}/missing.pddl ${WORK}/problem.pddl ${WORK}/good.plan)
expect_run(2 "${WORK}: error: cannot open the file: it is a directory" ${ALPLAN} validate ${task} ${WORK})
