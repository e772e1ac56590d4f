# PDDL+ sections refused by name, and constructs used without their
# :requirements flag warned about (at their place; -q silences them).
# Variables: ALPLAN, SHARED, DATA, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

file(WRITE ${WORK}/plus.pddl "(define (domain tank)
  (:requirements :time :numeric-fluents)
  (:functions (level))
  (:process fill :parameters () :precondition (< (level) 10) :effect (increase (level) (* #t 1)))
  (:event full :parameters () :precondition (>= (level) 10) :effect (assign (level) 10)))
")
expect_run(2 "plus.pddl:4:4: error: PDDL+ processes (:process) are not supported" ${ALPLAN} parse ${WORK}/plus.pddl)
expect_run(2 "plus.pddl:5:4: error: PDDL+ events (:event) are not supported" ${ALPLAN} parse ${WORK}/plus.pddl)

# Declares :strips only, uses types, a negative precondition, a number.
file(WRITE ${WORK}/lax.pddl "(define (domain lax)
  (:requirements :strips)
  (:types room)
  (:predicates (at ?r - room) (lit ?r - room))
  (:functions (power))
  (:action light :parameters (?r - room)
    :precondition (and (at ?r) (not (lit ?r)))
    :effect (and (lit ?r) (decrease (power) 1))))
")
file(WRITE ${WORK}/lax-problem.pddl "(define (problem one) (:domain lax)
  (:objects hall - room) (:init (at hall) (= (power) 5)) (:goal (lit hall)))
")
expect_run(0 "lax.pddl:3:11: warning: the type room is used without the requirement :typing (or :adl)"
  ${ALPLAN} parse ${WORK}/lax.pddl)
expect_run(0 "lax.pddl:5:15: warning: the numeric function (power) is used without the requirement :numeric-fluents"
  ${ALPLAN} parse ${WORK}/lax.pddl)
expect_run(0 "lax.pddl:7:32: warning: a negative condition (not (lit ...)) is used without the requirement :negative-preconditions (or :adl)"
  ${ALPLAN} parse ${WORK}/lax.pddl)
expect_run_without(0 "warning" ${ALPLAN} parse -q ${WORK}/lax.pddl)
expect_run(0 "without the requirement :negative-preconditions" ${ALPLAN} plan ${WORK}/lax.pddl ${WORK}/lax-problem.pddl)
expect_run_without(0 "warning" ${ALPLAN} plan -q ${WORK}/lax.pddl ${WORK}/lax-problem.pddl)

# Declared, nothing is said; :adl covers its parts, :fluents numbers.
file(READ ${WORK}/lax.pddl lax)
string(REPLACE "(:requirements :strips)" "(:requirements :adl :fluents)" declared "${lax}")
file(WRITE ${WORK}/declared.pddl "${declared}")
expect_run_without(0 "warning" ${ALPLAN} parse ${WORK}/declared.pddl)
