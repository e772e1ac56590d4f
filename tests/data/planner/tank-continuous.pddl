; A continuous effect (PDDL 2.1 level 4): the fill raises the level at 2 per time unit.
(define (domain tank) (:requirements :durative-actions :fluents :continuous-effects)
  (:predicates (open))
  (:functions (level))
  (:durative-action fill :parameters () :duration (= ?duration 5)
    :condition (at start (open))
    :effect (increase (level) (* #t 2))))
