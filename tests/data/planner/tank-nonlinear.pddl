; Change that is not linear in #t: the planner refuses it and names it with its place.
(define (domain tank) (:requirements :durative-actions :fluents :continuous-effects)
  (:predicates (open))
  (:functions (level))
  (:durative-action fill :parameters () :duration (= ?duration 5)
    :condition (at start (open))
    :effect (increase (level) (* #t (* #t 2)))))
