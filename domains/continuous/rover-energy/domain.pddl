; A simple planetary rover (after the IPC-2002 Rovers domain) whose energy
; changes continuously.
;
; - Driving between waypoints takes (distance / speed) and drains the
;   rover's energy at (drive-rate ?r) per time unit; sampling soil or rock,
;   taking an image and sending data drain it at (work-rate ?r) for their
;   fixed times. Energy must stay at or above zero over all of each of them.
; - At a sunny waypoint the rover recharges: energy rises at the waypoint's
;   (sunlight ?w) for a duration of the planner's choice, bounded so that the
;   rover never goes above (max-energy ?r) (it may work while it charges).
; - Data reach a lander from a waypoint in its range, one rover at a time.
;   The goals are communicated soil, rock and image data.
(define (domain rover-energy)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types rover waypoint objective lander - object)

  (:predicates
    (at ?r - rover ?w - waypoint)
    (path ?from - waypoint ?to - waypoint)
    (sunny ?w - waypoint)
    (in-range ?w - waypoint ?l - lander)     ; a rover at ?w can talk to ?l
    (channel-free ?l - lander)
    (panels-free ?r - rover)                 ; not recharging
    (equipped-soil ?r - rover)
    (equipped-rock ?r - rover)
    (equipped-camera ?r - rover)
    (soil-at ?w - waypoint)
    (rock-at ?w - waypoint)
    (visible-from ?o - objective ?w - waypoint)
    (have-soil ?r - rover ?w - waypoint)
    (have-rock ?r - rover ?w - waypoint)
    (have-image ?r - rover ?o - objective)
    (communicated-soil ?w - waypoint)
    (communicated-rock ?w - waypoint)
    (communicated-image ?o - objective))

  (:functions
    (energy ?r - rover) - number
    (max-energy ?r - rover) - number
    (speed ?r - rover) - number
    (drive-rate ?r - rover) - number         ; energy a time unit while driving
    (work-rate ?r - rover) - number          ; energy a time unit while sampling, imaging, sending
    (distance ?from - waypoint ?to - waypoint) - number
    (sunlight ?w - waypoint) - number        ; energy a time unit while recharging there
    (sample-time) - number
    (image-time) - number
    (comm-time) - number)

  (:durative-action navigate
    :parameters (?r - rover ?from - waypoint ?to - waypoint)
    :duration (= ?duration (/ (distance ?from ?to) (speed ?r)))
    :condition (and (at start (at ?r ?from))
                    (over all (path ?from ?to))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at start (not (at ?r ?from)))
                 (at end (at ?r ?to))
                 (decrease (energy ?r) (* #t (drive-rate ?r)))))

  (:durative-action recharge
    :parameters (?r - rover ?w - waypoint)
    :duration (and (>= ?duration 1)
                   (<= ?duration (/ (- (max-energy ?r) (energy ?r)) (sunlight ?w))))
    :condition (and (at start (sunny ?w))
                    (at start (panels-free ?r))
                    (over all (at ?r ?w))
                    (over all (<= (energy ?r) (max-energy ?r))))
    :effect (and (at start (not (panels-free ?r)))
                 (at end (panels-free ?r))
                 (increase (energy ?r) (* #t (sunlight ?w)))))

  (:durative-action sample-soil
    :parameters (?r - rover ?w - waypoint)
    :duration (= ?duration (sample-time))
    :condition (and (at start (soil-at ?w))
                    (at start (equipped-soil ?r))
                    (over all (at ?r ?w))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at start (not (soil-at ?w)))
                 (at end (have-soil ?r ?w))
                 (decrease (energy ?r) (* #t (work-rate ?r)))))

  (:durative-action sample-rock
    :parameters (?r - rover ?w - waypoint)
    :duration (= ?duration (sample-time))
    :condition (and (at start (rock-at ?w))
                    (at start (equipped-rock ?r))
                    (over all (at ?r ?w))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at start (not (rock-at ?w)))
                 (at end (have-rock ?r ?w))
                 (decrease (energy ?r) (* #t (work-rate ?r)))))

  (:durative-action take-image
    :parameters (?r - rover ?o - objective ?w - waypoint)
    :duration (= ?duration (image-time))
    :condition (and (at start (visible-from ?o ?w))
                    (at start (equipped-camera ?r))
                    (over all (at ?r ?w))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at end (have-image ?r ?o))
                 (decrease (energy ?r) (* #t (work-rate ?r)))))

  (:durative-action communicate-soil
    :parameters (?r - rover ?l - lander ?w - waypoint ?x - waypoint)
    :duration (= ?duration (comm-time))
    :condition (and (at start (have-soil ?r ?w))
                    (at start (channel-free ?l))
                    (over all (at ?r ?x))
                    (over all (in-range ?x ?l))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at start (not (channel-free ?l)))
                 (at end (channel-free ?l))
                 (at end (communicated-soil ?w))
                 (decrease (energy ?r) (* #t (work-rate ?r)))))

  (:durative-action communicate-rock
    :parameters (?r - rover ?l - lander ?w - waypoint ?x - waypoint)
    :duration (= ?duration (comm-time))
    :condition (and (at start (have-rock ?r ?w))
                    (at start (channel-free ?l))
                    (over all (at ?r ?x))
                    (over all (in-range ?x ?l))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at start (not (channel-free ?l)))
                 (at end (channel-free ?l))
                 (at end (communicated-rock ?w))
                 (decrease (energy ?r) (* #t (work-rate ?r)))))

  (:durative-action communicate-image
    :parameters (?r - rover ?l - lander ?o - objective ?x - waypoint)
    :duration (= ?duration (comm-time))
    :condition (and (at start (have-image ?r ?o))
                    (at start (channel-free ?l))
                    (over all (at ?r ?x))
                    (over all (in-range ?x ?l))
                    (over all (>= (energy ?r) 0)))
    :effect (and (at start (not (channel-free ?l)))
                 (at end (channel-free ?l))
                 (at end (communicated-image ?o))
                 (decrease (energy ?r) (* #t (work-rate ?r)))))
)
