; One generator runs 150 time units on a 50-unit tank holding 40: it needs 110 units more,
; and only all three tanks together (40 + 45 + 40) give that much.
(define (problem generator-p02) (:domain generator)
  (:objects
    gen1 - generator
    tank1 tank2 tank3 - tank)
  (:init
    (ready gen1)
    (= (fuel gen1) 40) (= (capacity gen1) 50) (= (burn-rate gen1) 1) (= (run-time gen1) 150)
    (available tank1) (= (refuel-rate tank1) 4) (= (refuel-time tank1) 10)
    (available tank2) (= (refuel-rate tank2) 3) (= (refuel-time tank2) 15)
    (available tank3) (= (refuel-rate tank3) 2) (= (refuel-time tank3) 20))
  (:goal (and (generator-ran gen1)))
  (:metric minimize (total-time)))
