; Two robots, four seniors, eight locations in two wings joined by corridors; docks in
; sunroom1 and library1; the remedies wait in kitchen1. Each robot starts at a dock with too
; little charge for one move above its reserve, so a robot must recharge before it moves.
(define (problem robot-battery-p02) (:domain robot_battery)
  (:objects
    robot1 robot2 - robot
    senior1 senior2 senior3 senior4 - senior
    sunroom1 corridor1 corridor2 kitchen1 bedroom1 bedroom2 bedroom3 library1 - location
    remedy1 remedy2 remedy3 remedy4 - remedy)
  (:init
    (be robot1 sunroom1) (hand_empty robot1) (= (battery robot1) 15) (= (capacity robot1) 100) (= (reserve robot1) 10)
    (= (drain_rate robot1) 1) (= (charge_rate robot1) 5)
    (be robot2 library1) (hand_empty robot2) (= (battery robot2) 12) (= (capacity robot2) 90) (= (reserve robot2) 10)
    (= (drain_rate robot2) 1) (= (charge_rate robot2) 4)
    (dock_free sunroom1) (dock_free library1)
    (be senior1 bedroom1) (be senior2 bedroom2) (be senior3 bedroom3) (be senior4 library1)
    (be remedy1 kitchen1) (be remedy2 kitchen1) (be remedy3 kitchen1) (be remedy4 kitchen1)
    (prescribed remedy1 senior1) (prescribed remedy2 senior2) (prescribed remedy3 senior3) (prescribed remedy4 senior4)
    (path sunroom1 corridor1) (path corridor1 sunroom1) (= (moving_time sunroom1 corridor1) 10) (= (moving_time corridor1 sunroom1) 10)
    (path kitchen1 corridor1) (path corridor1 kitchen1) (= (moving_time kitchen1 corridor1) 10) (= (moving_time corridor1 kitchen1) 10)
    (path bedroom1 corridor1) (path corridor1 bedroom1) (= (moving_time bedroom1 corridor1) 10) (= (moving_time corridor1 bedroom1) 10)
    (path corridor1 corridor2) (path corridor2 corridor1) (= (moving_time corridor1 corridor2) 15) (= (moving_time corridor2 corridor1) 15)
    (path corridor2 bedroom2) (path bedroom2 corridor2) (= (moving_time corridor2 bedroom2) 10) (= (moving_time bedroom2 corridor2) 10)
    (path corridor2 bedroom3) (path bedroom3 corridor2) (= (moving_time corridor2 bedroom3) 10) (= (moving_time bedroom3 corridor2) 10)
    (path corridor2 library1) (path library1 corridor2) (= (moving_time corridor2 library1) 10) (= (moving_time library1 corridor2) 10)
    (= (handling_time) 5))
  (:goal (and (treated senior1) (treated senior2) (treated senior3) (treated senior4)))
  (:metric minimize (total-time)))
