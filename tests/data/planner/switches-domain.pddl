; A classical task: no durative action, no timed literal. `alplan plan`
; prints its plans sequentially, with a cost line (tests/cli/plan_output_test.cmake).
(define (domain switches)
  (:requirements :strips :negative-preconditions)
  (:predicates (on-a) (on-b) (locked))
  (:action switch-a :parameters () :precondition (not (on-a)) :effect (on-a))
  (:action switch-b :parameters () :precondition (on-a) :effect (and (on-b) (locked))))
