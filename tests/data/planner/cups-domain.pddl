; Any one of the cups serves: one plan per cup, each two 2 actions apart
; (plan --diverse, planner/diverse_plans.h).
(define (domain cups) (:requirements :typing :durative-actions)
  (:types cup)
  (:predicates (available ?c - cup) (served))
  (:durative-action serve :parameters (?c - cup) :duration (= ?duration 5)
    :condition (at start (available ?c)) :effect (at end (served))))
