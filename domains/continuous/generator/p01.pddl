; One generator must run 100 time units on a 60-unit tank: two tanks must
; refuel it while it runs, each adding 30 units over 10 time units.
(define (problem generator-p01) (:domain generator)
  (:objects
    gen1 - generator
    tank1 tank2 - tank)
  (:init
    (ready gen1)
    (= (fuel gen1) 60) (= (capacity gen1) 60) (= (burn-rate gen1) 1) (= (run-time gen1) 100)
    (available tank1) (= (refuel-rate tank1) 3) (= (refuel-time tank1) 10)
    (available tank2) (= (refuel-rate tank2) 3) (= (refuel-time tank2) 10))
  (:goal (generator-ran gen1))
  (:metric minimize (total-time)))
