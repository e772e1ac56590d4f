; Two generators run at once: gen1 needs 120 units (holds 50), gen2 burns 2 a unit for 80 units
; (needs 160, holds 40). Five tanks of different rates and times; 190 units must come from tanks.
(define (problem generator-p03) (:domain generator)
  (:objects
    gen1 gen2 - generator
    tank1 tank2 tank3 tank4 tank5 - tank)
  (:init
    (ready gen1)
    (= (fuel gen1) 50) (= (capacity gen1) 50) (= (burn-rate gen1) 1) (= (run-time gen1) 120)
    (ready gen2)
    (= (fuel gen2) 40) (= (capacity gen2) 60) (= (burn-rate gen2) 2) (= (run-time gen2) 80)
    (available tank1) (= (refuel-rate tank1) 4) (= (refuel-time tank1) 10)
    (available tank2) (= (refuel-rate tank2) 4) (= (refuel-time tank2) 10)
    (available tank3) (= (refuel-rate tank3) 5) (= (refuel-time tank3) 10)
    (available tank4) (= (refuel-rate tank4) 6) (= (refuel-time tank4) 10)
    (available tank5) (= (refuel-rate tank5) 3) (= (refuel-time tank5) 15))
  (:goal (and (generator-ran gen1) (generator-ran gen2)))
  (:metric minimize (total-time)))
