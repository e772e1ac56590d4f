; Two rovers (rover1 samples soil, rover2 rock, both have cameras), six goals on seven
; waypoints, three sunny. The samples, images and sends alone cost 6 * (5 + 4) = 54 units of
; energy; the rovers have 20 + 15 = 35.
(define (problem rover-energy-p03) (:domain rover-energy)
  (:objects
    rover1 rover2 - rover
    w0 w1 w2 w3 w4 w5 w6 - waypoint
    obj1 obj2 - objective
    lander1 - lander)
  (:init
    (at rover1 w0) (panels-free rover1) (equipped-soil rover1) (equipped-camera rover1)
    (= (energy rover1) 20) (= (max-energy rover1) 70) (= (speed rover1) 1) (= (drive-rate rover1) 1) (= (work-rate rover1) 1)
    (at rover2 w0) (panels-free rover2) (equipped-rock rover2) (equipped-camera rover2)
    (= (energy rover2) 15) (= (max-energy rover2) 60) (= (speed rover2) 2) (= (drive-rate rover2) 3) (= (work-rate rover2) 1)
    (path w0 w1) (path w1 w0) (= (distance w0 w1) 10) (= (distance w1 w0) 10)
    (path w0 w2) (path w2 w0) (= (distance w0 w2) 10) (= (distance w2 w0) 10)
    (path w1 w3) (path w3 w1) (= (distance w1 w3) 12) (= (distance w3 w1) 12)
    (path w1 w4) (path w4 w1) (= (distance w1 w4) 8) (= (distance w4 w1) 8)
    (path w2 w5) (path w5 w2) (= (distance w2 w5) 10) (= (distance w5 w2) 10)
    (path w5 w6) (path w6 w5) (= (distance w5 w6) 8) (= (distance w6 w5) 8)
    (path w4 w5) (path w5 w4) (= (distance w4 w5) 14) (= (distance w5 w4) 14)
    (path w3 w4) (path w4 w3) (= (distance w3 w4) 10) (= (distance w4 w3) 10)
    (sunny w0) (= (sunlight w0) 2) (sunny w1) (= (sunlight w1) 3) (sunny w5) (= (sunlight w5) 4)
    (soil-at w3) (soil-at w4) (rock-at w5) (rock-at w6)
    (visible-from obj1 w3) (visible-from obj2 w6) (visible-from obj2 w2)
    (channel-free lander1) (in-range w0 lander1) (in-range w4 lander1)
    (= (sample-time) 5) (= (image-time) 5) (= (comm-time) 4))
  (:goal (and (communicated-soil w3) (communicated-soil w4) (communicated-rock w5) (communicated-rock w6) (communicated-image obj1) (communicated-image obj2)))
  (:metric minimize (total-time)))
