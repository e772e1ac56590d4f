(define (problem three-cups) (:domain cups) (:objects c1 c2 c3 - cup)
  (:init (available c1) (available c2) (available c3)) (:goal (served)))
