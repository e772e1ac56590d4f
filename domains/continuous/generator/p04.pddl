; Three generators run at once for 200, 120 and 180 time units; they hold 60, 50 and 20 units
; of the 200 + 240 + 180 they burn, so 490 units must come from ten tanks (560 in all).
(define (problem generator-p04) (:domain generator)
  (:objects
    gen1 gen2 gen3 - generator
    tank1 tank2 tank3 tank4 tank5 tank6 tank7 tank8 tank9 tank10 - tank)
  (:init
    (ready gen1)
    (= (fuel gen1) 60) (= (capacity gen1) 60) (= (burn-rate gen1) 1) (= (run-time gen1) 200)
    (ready gen2)
    (= (fuel gen2) 50) (= (capacity gen2) 80) (= (burn-rate gen2) 2) (= (run-time gen2) 120)
    (ready gen3)
    (= (fuel gen3) 20) (= (capacity gen3) 40) (= (burn-rate gen3) 1) (= (run-time gen3) 180)
    (available tank1) (= (refuel-rate tank1) 5) (= (refuel-time tank1) 10)
    (available tank2) (= (refuel-rate tank2) 5) (= (refuel-time tank2) 10)
    (available tank3) (= (refuel-rate tank3) 5) (= (refuel-time tank3) 10)
    (available tank4) (= (refuel-rate tank4) 8) (= (refuel-time tank4) 10)
    (available tank5) (= (refuel-rate tank5) 6) (= (refuel-time tank5) 15)
    (available tank6) (= (refuel-rate tank6) 7) (= (refuel-time tank6) 10)
    (available tank7) (= (refuel-rate tank7) 3) (= (refuel-time tank7) 15)
    (available tank8) (= (refuel-rate tank8) 4) (= (refuel-time tank8) 10)
    (available tank9) (= (refuel-rate tank9) 3) (= (refuel-time tank9) 15)
    (available tank10) (= (refuel-rate tank10) 4) (= (refuel-time tank10) 10))
  (:goal (and (generator-ran gen1) (generator-ran gen2) (generator-ran gen3)))
  (:metric minimize (total-time)))
