(define (problem p) (:domain mixed) (:objects a b island - place) (:init (at a) (home a) (road a b) (road b a) (= (fuel) 2) (= (cost) 0)) (:goal (at island)))
