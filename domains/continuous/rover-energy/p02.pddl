; One rover, four goals on five waypoints; two are sunny (w1 bright, w4 dim). The samples,
; images and sends alone cost 4 * (5 + 4) = 36 units of energy; the rover has 25.
(define (problem rover-energy-p02) (:domain rover-energy)
  (:objects
    rover1 - rover
    w0 w1 w2 w3 w4 - waypoint
    obj1 obj2 - objective
    lander1 - lander)
  (:init
    (at rover1 w0) (panels-free rover1) (equipped-soil rover1) (equipped-rock rover1) (equipped-camera rover1)
    (= (energy rover1) 25) (= (max-energy rover1) 80) (= (speed rover1) 2) (= (drive-rate rover1) 2) (= (work-rate rover1) 1)
    (path w0 w1) (path w1 w0) (= (distance w0 w1) 10) (= (distance w1 w0) 10)
    (path w1 w2) (path w2 w1) (= (distance w1 w2) 8) (= (distance w2 w1) 8)
    (path w1 w3) (path w3 w1) (= (distance w1 w3) 12) (= (distance w3 w1) 12)
    (path w3 w4) (path w4 w3) (= (distance w3 w4) 6) (= (distance w4 w3) 6)
    (path w2 w4) (path w4 w2) (= (distance w2 w4) 16) (= (distance w4 w2) 16)
    (sunny w1) (= (sunlight w1) 4) (sunny w4) (= (sunlight w4) 2)
    (soil-at w2) (rock-at w3)
    (visible-from obj1 w3) (visible-from obj2 w4)
    (channel-free lander1) (in-range w0 lander1) (in-range w1 lander1)
    (= (sample-time) 5) (= (image-time) 5) (= (comm-time) 4))
  (:goal (and (communicated-soil w2) (communicated-rock w3) (communicated-image obj1) (communicated-image obj2)))
  (:metric minimize (total-time)))
