
(define (problem p) (:domain mixed) (:objects a b c d - place)
  (:init (at a) (home a) (road a b) (road b a) (road a c) (road c a) (road c d) (road d c) (= (fuel) 2) (= (cost) 0))
  (:goal (and (explored) (at a))) (:metric minimize (cost)))
