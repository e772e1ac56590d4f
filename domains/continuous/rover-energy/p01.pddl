; One rover, three goals on a line of waypoints w0 - w1 - w2: soil at w1,
; rock and the objective at w2, the lander in range of w0 only. The round
; trip and the work take 67 units of energy; the rover has 30, so it must
; recharge at w1, the only sunny waypoint.
(define (problem rover-energy-p01) (:domain rover-energy)
  (:objects
    rover1 - rover
    w0 w1 w2 - waypoint
    obj1 - objective
    lander1 - lander)
  (:init
    (at rover1 w0) (panels-free rover1)
    (equipped-soil rover1) (equipped-rock rover1) (equipped-camera rover1)
    (= (energy rover1) 30) (= (max-energy rover1) 60)
    (= (speed rover1) 1) (= (drive-rate rover1) 1) (= (work-rate rover1) 1)
    (path w0 w1) (path w1 w0) (= (distance w0 w1) 10) (= (distance w1 w0) 10)
    (path w1 w2) (path w2 w1) (= (distance w1 w2) 10) (= (distance w2 w1) 10)
    (sunny w1) (= (sunlight w1) 3)
    (soil-at w1) (rock-at w2) (visible-from obj1 w2)
    (in-range w0 lander1) (channel-free lander1)
    (= (sample-time) 5) (= (image-time) 5) (= (comm-time) 4))
  (:goal (and (communicated-soil w1) (communicated-rock w2) (communicated-image obj1)))
  (:metric minimize (total-time)))
