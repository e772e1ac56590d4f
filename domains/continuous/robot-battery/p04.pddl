; Two robots, six seniors, twelve locations in three wings; docks in sunroom1 and sunroom2,
; remedies in kitchen1 and library1 (at the two ends of the home). Each robot starts at a dock
; with too little charge for one move above its reserve.
(define (problem robot-battery-p04) (:domain robot_battery)
  (:objects
    robot1 robot2 - robot
    senior1 senior2 senior3 senior4 senior5 senior6 - senior
    sunroom1 sunroom2 corridor1 corridor2 corridor3 kitchen1 dinning_room1 library1 bedroom1 bedroom2 bedroom3 bedroom4 - location
    remedy1 remedy2 remedy3 remedy4 remedy5 remedy6 - remedy)
  (:init
    (be robot1 sunroom1) (hand_empty robot1) (= (battery robot1) 16) (= (capacity robot1) 100) (= (reserve robot1) 10)
    (= (drain_rate robot1) 1) (= (charge_rate robot1) 5)
    (be robot2 sunroom2) (hand_empty robot2) (= (battery robot2) 18) (= (capacity robot2) 160) (= (reserve robot2) 10)
    (= (drain_rate robot2) 1) (= (charge_rate robot2) 4)
    (dock_free sunroom1) (dock_free sunroom2)
    (be senior1 bedroom1) (be senior2 bedroom2) (be senior3 bedroom3) (be senior4 bedroom4) (be senior5 dinning_room1) (be senior6 sunroom2)
    (be remedy1 kitchen1) (be remedy2 kitchen1) (be remedy3 library1) (be remedy4 library1) (be remedy5 kitchen1) (be remedy6 library1)
    (prescribed remedy1 senior1) (prescribed remedy2 senior2) (prescribed remedy3 senior3) (prescribed remedy4 senior4) (prescribed remedy5 senior5) (prescribed remedy6 senior6)
    (path sunroom1 corridor1) (path corridor1 sunroom1) (= (moving_time sunroom1 corridor1) 10) (= (moving_time corridor1 sunroom1) 10)
    (path bedroom1 corridor1) (path corridor1 bedroom1) (= (moving_time bedroom1 corridor1) 10) (= (moving_time corridor1 bedroom1) 10)
    (path kitchen1 dinning_room1) (path dinning_room1 kitchen1) (= (moving_time kitchen1 dinning_room1) 8) (= (moving_time dinning_room1 kitchen1) 8)
    (path dinning_room1 corridor1) (path corridor1 dinning_room1) (= (moving_time dinning_room1 corridor1) 10) (= (moving_time corridor1 dinning_room1) 10)
    (path corridor1 corridor2) (path corridor2 corridor1) (= (moving_time corridor1 corridor2) 15) (= (moving_time corridor2 corridor1) 15)
    (path corridor2 bedroom2) (path bedroom2 corridor2) (= (moving_time corridor2 bedroom2) 10) (= (moving_time bedroom2 corridor2) 10)
    (path corridor2 sunroom2) (path sunroom2 corridor2) (= (moving_time corridor2 sunroom2) 10) (= (moving_time sunroom2 corridor2) 10)
    (path corridor2 corridor3) (path corridor3 corridor2) (= (moving_time corridor2 corridor3) 15) (= (moving_time corridor3 corridor2) 15)
    (path corridor3 bedroom3) (path bedroom3 corridor3) (= (moving_time corridor3 bedroom3) 10) (= (moving_time bedroom3 corridor3) 10)
    (path corridor3 bedroom4) (path bedroom4 corridor3) (= (moving_time corridor3 bedroom4) 10) (= (moving_time bedroom4 corridor3) 10)
    (path corridor3 library1) (path library1 corridor3) (= (moving_time corridor3 library1) 12) (= (moving_time library1 corridor3) 12)
    (= (handling_time) 5))
  (:goal (and (treated senior1) (treated senior2) (treated senior3) (treated senior4) (treated senior5) (treated senior6)))
  (:metric minimize (total-time)))
