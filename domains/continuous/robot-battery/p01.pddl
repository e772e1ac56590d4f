; One robot, one senior. robot1 waits at the dock in sunroom1 with 30 of
; its 100; each corridor takes 10 at 2 a unit, and its reserve is 10, so it
; can make one move before it must recharge. Fetching the remedy from
; kitchen1 and bringing it to bedroom1 takes four moves (80).
(define (problem robot-battery-p01) (:domain robot_battery)
  (:objects
    robot1 - robot
    senior1 - senior
    sunroom1 corridor1 kitchen1 bedroom1 - location
    remedy1 - remedy)
  (:init
    (be robot1 sunroom1) (hand_empty robot1)
    (= (battery robot1) 30) (= (capacity robot1) 100) (= (reserve robot1) 10)
    (= (drain_rate robot1) 2) (= (charge_rate robot1) 5)
    (dock_free sunroom1)
    (be senior1 bedroom1)
    (be remedy1 kitchen1) (prescribed remedy1 senior1)
    (path sunroom1 corridor1) (path corridor1 sunroom1) (= (moving_time sunroom1 corridor1) 10) (= (moving_time corridor1 sunroom1) 10)
    (path corridor1 kitchen1) (path kitchen1 corridor1) (= (moving_time corridor1 kitchen1) 10) (= (moving_time kitchen1 corridor1) 10)
    (path corridor1 bedroom1) (path bedroom1 corridor1) (= (moving_time corridor1 bedroom1) 10) (= (moving_time bedroom1 corridor1) 10)
    (= (handling_time) 5))
  (:goal (treated senior1))
  (:metric minimize (total-time)))
