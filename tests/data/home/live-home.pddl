; A small home for `alplan home --live` in tests: senior1 sits in the kitchen
; with robot1 and the glasses, and handing over takes 2 s, so that a
; terrified senior is soothed (carry, fill, give, receive) within seconds of
; wall time. senior2 is in the corridor beside it.
(define (problem live-home) (:domain assisted_living)
  (:objects
    robot1 - robot
    senior1 senior2 - senior
    corridor1 - corridor
    kitchen1 - kitchen
    glass_id01 glass_id02 - drinking_glass
    guitar_id01 - guitar)
  (:init
    (be robot1 kitchen1)
    (be senior1 kitchen1) (be senior2 corridor1)
    (be glass_id01 kitchen1) (be glass_id02 kitchen1) (be guitar_id01 kitchen1)
    (path kitchen1 corridor1) (path corridor1 kitchen1)
    (= (moving_time kitchen1 corridor1) 5) (= (moving_time corridor1 kitchen1) 5)
    (iot_tagged glass_id01) (iot_tagged glass_id02) (iot_tagged guitar_id01)
    (available glass_id01) (available glass_id02) (available guitar_id01)
    (= (handling_time) 2) (= (receiving_time) 2) (= (suggesting_time) 2)
    (= (suggestion_cost) 500) (= (total-cost) 0))
  (:goal (and))
  (:metric minimize (+ (total-time) (total-cost))))
