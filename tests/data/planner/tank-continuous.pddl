; A continuous effect: the planner refuses it and names it.
(define (domain tank) (:requirements :durative-actions :fluents :continuous-effects)
  (:predicates (open))
  (:functions (level))
  (:durative-action fill :parameters () :duration (= ?duration 5)
    :condition (at start (open))
    :effect (increase (level) (* #t 2))))
