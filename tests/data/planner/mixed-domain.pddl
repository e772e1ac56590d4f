
; Numeric fluents, negative preconditions, a conditional effect and a derived
; predicate in one small domain (planner tests).
(define (domain mixed) (:requirements :typing :durative-actions :fluents :negative-preconditions
                                      :conditional-effects :derived-predicates)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place) (visited ?p - place) (broken) (explored) (home ?p - place))
  (:functions (fuel) (cost))
  (:derived (explored) (forall (?p - place) (visited ?p)))
  (:durative-action drive :parameters (?a ?b - place) :duration (= ?duration 2)
    :condition (and (at start (at ?a)) (at start (road ?a ?b)) (at start (>= (fuel) 1)) (over all (not (broken))))
    :effect (and (at start (not (at ?a))) (at end (at ?b)) (at end (visited ?b)) (at start (decrease (fuel) 1))
                 (at end (increase (cost) 1))))
  (:action refuel :parameters (?p - place)
    :precondition (and (at ?p) (home ?p) (< (fuel) 2))
    :effect (and (assign (fuel) 4) (when (not (visited ?p)) (visited ?p)))))
