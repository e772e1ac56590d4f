; The home `alplan home --battery` runs by default: ../home.pddl with batteries (battery/domain.pddl):
; a dock in corridor2, the home's most central room (the least moving time to every other room), where
; robot2 stands; each robot's battery full at 100, a reserve of 20, a drain of 0.05 a second of moving
; (a 280 s round trip from a bedroom to the kitchen costs 14) and a charge of 0.5 a second.
; These are the defaults of `alplan home --battery` (home/home_settings.h, BatteryOptions).
; ../home.pddl says:
; The home `alplan home` runs by default: the paper's home of Section 4 with its eight seniors, a
; second robot docked in corridor2, and every object available but the violin and the PCs (in use,
; as in the paper's Scenarios 2 and 3). Nobody is stressed at the start: `alplan home` perceives the
; seniors over time, and its goals, emotions and comfort windows replace the empty goal below.
; Layout, durations and the hydration window are ours (the paper gives the rooms and
; the times of its plans, from which the moving times follow).
(define (problem home) (:domain assisted_living)
  (:objects
    robot1 robot2 - robot
    senior1 senior2 senior3 senior4 senior5 senior6 senior7 senior8 - senior
    corridor1 corridor2 corridor3 - corridor
    bedroom1 bedroom2 bedroom3 bedroom4 - bedroom
    kitchen1 - kitchen  music_room1 - music_room  library1 - library  dinning_room1 - dinning_room
    sunroom1 sunroom2 - sunroom
    glass_id01 glass_id02 glass_id03 glass_id04 glass_id05 glass_id06 glass_id07 glass_id08 - drinking_glass
    violin_id01 - violin  guitar_id01 - guitar
    pc_id01 pc_id02 - desktop  tv_id01 - tv
    book_id01 - book  magazine_id01 - magazine)
  (:init
    (be robot1 bedroom1) (be robot2 corridor2)
    (be senior1 bedroom1) (be senior2 bedroom2) (be senior3 bedroom3) (be senior4 bedroom4) (be senior5 sunroom1) (be senior6 sunroom2) (be senior7 library1) (be senior8 dinning_room1)
    (be glass_id01 kitchen1) (be glass_id02 kitchen1) (be glass_id03 kitchen1) (be glass_id04 kitchen1) (be glass_id05 kitchen1) (be glass_id06 kitchen1) (be glass_id07 kitchen1) (be glass_id08 kitchen1)
    (be violin_id01 music_room1) (be guitar_id01 music_room1)
    (be book_id01 library1) (be magazine_id01 library1)
    (be pc_id01 library1) (be pc_id02 library1) (be tv_id01 library1)
    ; IoT-tagged: every object of the paper's home (its Section 4); new objects are not
    (iot_tagged glass_id01) (iot_tagged glass_id02) (iot_tagged glass_id03) (iot_tagged glass_id04) (iot_tagged glass_id05) (iot_tagged glass_id06) (iot_tagged glass_id07) (iot_tagged glass_id08)
    (iot_tagged violin_id01) (iot_tagged guitar_id01) (iot_tagged book_id01) (iot_tagged magazine_id01)
    (iot_tagged pc_id01) (iot_tagged pc_id02) (iot_tagged tv_id01)
    (available glass_id01) (available glass_id02) (available glass_id03) (available glass_id04)
    (available glass_id05) (available glass_id06) (available glass_id07) (available glass_id08)
    (available guitar_id01) (available book_id01) (available magazine_id01) (available tv_id01)
    (path bedroom1 corridor1) (path corridor1 bedroom1) (= (moving_time bedroom1 corridor1) 30) (= (moving_time corridor1 bedroom1) 30)
    (path bedroom2 corridor1) (path corridor1 bedroom2) (= (moving_time bedroom2 corridor1) 30) (= (moving_time corridor1 bedroom2) 30)
    (path sunroom1 corridor1) (path corridor1 sunroom1) (= (moving_time sunroom1 corridor1) 25) (= (moving_time corridor1 sunroom1) 25)
    (path corridor1 corridor2) (path corridor2 corridor1) (= (moving_time corridor1 corridor2) 50) (= (moving_time corridor2 corridor1) 50)
    (path corridor2 dinning_room1) (path dinning_room1 corridor2) (= (moving_time corridor2 dinning_room1) 40) (= (moving_time dinning_room1 corridor2) 40)
    (path corridor2 music_room1) (path music_room1 corridor2) (= (moving_time corridor2 music_room1) 40) (= (moving_time music_room1 corridor2) 40)
    (path corridor2 library1) (path library1 corridor2) (= (moving_time corridor2 library1) 40) (= (moving_time library1 corridor2) 40)
    (path corridor2 corridor3) (path corridor3 corridor2) (= (moving_time corridor2 corridor3) 50) (= (moving_time corridor3 corridor2) 50)
    (path corridor3 bedroom3) (path bedroom3 corridor3) (= (moving_time corridor3 bedroom3) 30) (= (moving_time bedroom3 corridor3) 30)
    (path corridor3 bedroom4) (path bedroom4 corridor3) (= (moving_time corridor3 bedroom4) 30) (= (moving_time bedroom4 corridor3) 30)
    (path corridor3 sunroom2) (path sunroom2 corridor3) (= (moving_time corridor3 sunroom2) 25) (= (moving_time sunroom2 corridor3) 25)
    (path dinning_room1 kitchen1) (path kitchen1 dinning_room1) (= (moving_time dinning_room1 kitchen1) 20) (= (moving_time kitchen1 dinning_room1) 20)
    (= (handling_time) 10) (= (receiving_time) 10) (= (suggesting_time) 5)
    (= (suggestion_cost) 500) (= (total-cost) 0)
    (dock corridor2)
    (= (battery robot1) 100) (= (capacity robot1) 100) (= (reserve robot1) 20) (= (drain_rate robot1) 0.05) (= (charge_rate robot1) 0.5)
    (= (battery robot2) 100) (= (capacity robot2) 100) (= (reserve robot2) 20) (= (drain_rate robot2) 0.05) (= (charge_rate robot2) 0.5))
  (:goal (and))
  (:metric minimize (+ (total-time) (total-cost))))
