; A lamp and a door, for PDDL 3 constraints the planner must refuse by name.
(define (domain lamp)
  (:requirements :strips :durative-actions :constraints)
  (:predicates (lit) (open))
  (:durative-action switch-on :parameters () :duration (= ?duration 2)
    :condition (at start (not (lit))) :effect (at end (lit)))
  (:durative-action open-door :parameters () :duration (= ?duration 3)
    :effect (at end (open))))
