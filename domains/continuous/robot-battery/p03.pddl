; Two robots, five seniors, ten locations; docks in sunroom1 and sunroom2, remedies in
; kitchen1 and in the medicine cabinet of dinning_room1. Each robot starts at a dock with too
; little charge for one move above its reserve.
(define (problem robot-battery-p03) (:domain robot_battery)
  (:objects
    robot1 robot2 - robot
    senior1 senior2 senior3 senior4 senior5 - senior
    sunroom1 sunroom2 corridor1 corridor2 corridor3 kitchen1 dinning_room1 bedroom1 bedroom2 bedroom3 - location
    remedy1 remedy2 remedy3 remedy4 remedy5 - remedy)
  (:init
    (be robot1 sunroom1) (hand_empty robot1) (= (battery robot1) 15) (= (capacity robot1) 100) (= (reserve robot1) 10)
    (= (drain_rate robot1) 1) (= (charge_rate robot1) 5)
    (be robot2 sunroom2) (hand_empty robot2) (= (battery robot2) 15) (= (capacity robot2) 110) (= (reserve robot2) 8)
    (= (drain_rate robot2) 1) (= (charge_rate robot2) 3)
    (dock_free sunroom1) (dock_free sunroom2)
    (be senior1 bedroom1) (be senior2 bedroom2) (be senior3 bedroom3) (be senior4 sunroom2) (be senior5 dinning_room1)
    (be remedy1 kitchen1) (be remedy2 kitchen1) (be remedy3 dinning_room1) (be remedy4 dinning_room1) (be remedy5 kitchen1)
    (prescribed remedy1 senior1) (prescribed remedy2 senior2) (prescribed remedy3 senior3) (prescribed remedy4 senior4) (prescribed remedy5 senior5)
    (path sunroom1 corridor1) (path corridor1 sunroom1) (= (moving_time sunroom1 corridor1) 10) (= (moving_time corridor1 sunroom1) 10)
    (path bedroom1 corridor1) (path corridor1 bedroom1) (= (moving_time bedroom1 corridor1) 10) (= (moving_time corridor1 bedroom1) 10)
    (path kitchen1 corridor1) (path corridor1 kitchen1) (= (moving_time kitchen1 corridor1) 12) (= (moving_time corridor1 kitchen1) 12)
    (path corridor1 corridor2) (path corridor2 corridor1) (= (moving_time corridor1 corridor2) 15) (= (moving_time corridor2 corridor1) 15)
    (path corridor2 dinning_room1) (path dinning_room1 corridor2) (= (moving_time corridor2 dinning_room1) 10) (= (moving_time dinning_room1 corridor2) 10)
    (path corridor2 bedroom2) (path bedroom2 corridor2) (= (moving_time corridor2 bedroom2) 10) (= (moving_time bedroom2 corridor2) 10)
    (path corridor2 corridor3) (path corridor3 corridor2) (= (moving_time corridor2 corridor3) 15) (= (moving_time corridor3 corridor2) 15)
    (path corridor3 bedroom3) (path bedroom3 corridor3) (= (moving_time corridor3 bedroom3) 10) (= (moving_time bedroom3 corridor3) 10)
    (path corridor3 sunroom2) (path sunroom2 corridor3) (= (moving_time corridor3 sunroom2) 10) (= (moving_time sunroom2 corridor3) 10)
    (path dinning_room1 kitchen1) (path kitchen1 dinning_room1) (= (moving_time dinning_room1 kitchen1) 8) (= (moving_time kitchen1 dinning_room1) 8)
    (= (handling_time) 5))
  (:goal (and (treated senior1) (treated senior2) (treated senior3) (treated senior4) (treated senior5)))
  (:metric minimize (total-time)))
