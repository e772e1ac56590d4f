; Two rovers, eight goals on nine waypoints, four sunny, two landers. The samples, images
; and sends alone cost 8 * (5 + 4) = 72 units of energy; the rovers have 28 + 20 = 48.
(define (problem rover-energy-p04) (:domain rover-energy)
  (:objects
    rover1 rover2 - rover
    w0 w1 w2 w3 w4 w5 w6 w7 w8 - waypoint
    obj1 obj2 obj3 - objective
    lander1 lander2 - lander)
  (:init
    (at rover1 w0) (panels-free rover1) (equipped-soil rover1) (equipped-rock rover1) (equipped-camera rover1)
    (= (energy rover1) 28) (= (max-energy rover1) 80) (= (speed rover1) 1) (= (drive-rate rover1) 1) (= (work-rate rover1) 1)
    (at rover2 w7) (panels-free rover2) (equipped-soil rover2) (equipped-rock rover2) (equipped-camera rover2)
    (= (energy rover2) 20) (= (max-energy rover2) 60) (= (speed rover2) 2) (= (drive-rate rover2) 3) (= (work-rate rover2) 1)
    (path w0 w1) (path w1 w0) (= (distance w0 w1) 10) (= (distance w1 w0) 10)
    (path w1 w2) (path w2 w1) (= (distance w1 w2) 10) (= (distance w2 w1) 10)
    (path w2 w3) (path w3 w2) (= (distance w2 w3) 12) (= (distance w3 w2) 12)
    (path w0 w4) (path w4 w0) (= (distance w0 w4) 8) (= (distance w4 w0) 8)
    (path w4 w5) (path w5 w4) (= (distance w4 w5) 10) (= (distance w5 w4) 10)
    (path w5 w6) (path w6 w5) (= (distance w5 w6) 12) (= (distance w6 w5) 12)
    (path w6 w7) (path w7 w6) (= (distance w6 w7) 10) (= (distance w7 w6) 10)
    (path w7 w8) (path w8 w7) (= (distance w7 w8) 8) (= (distance w8 w7) 8)
    (path w3 w8) (path w8 w3) (= (distance w3 w8) 16) (= (distance w8 w3) 16)
    (path w1 w5) (path w5 w1) (= (distance w1 w5) 14) (= (distance w5 w1) 14)
    (sunny w0) (= (sunlight w0) 2) (sunny w2) (= (sunlight w2) 4) (sunny w5) (= (sunlight w5) 3) (sunny w7) (= (sunlight w7) 4)
    (soil-at w2) (soil-at w3) (soil-at w6) (rock-at w4) (rock-at w8)
    (visible-from obj1 w3) (visible-from obj2 w6) (visible-from obj3 w5) (visible-from obj3 w8)
    (channel-free lander1) (in-range w0 lander1) (in-range w1 lander1)
    (channel-free lander2) (in-range w7 lander2) (in-range w8 lander2)
    (= (sample-time) 5) (= (image-time) 5) (= (comm-time) 4))
  (:goal (and (communicated-soil w2) (communicated-soil w3) (communicated-soil w6) (communicated-rock w4) (communicated-rock w8) (communicated-image obj1) (communicated-image obj2) (communicated-image obj3)))
  (:metric minimize (total-time)))
