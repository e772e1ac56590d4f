; The assisted-living domain (domains/assisted_living/) with batteries: a
; robot brings each senior the remedy prescribed for them, and its battery
; changes continuously.
;
; - Moving along a corridor takes (moving_time ?l1 ?l2) and drains the
;   robot's battery at (drain_rate ?robot) per time unit; the battery must
;   stay at or above the robot's (reserve ?robot) over all of every move.
;   Carrying and giving do not drain it.
; - In a room with a dock a robot recharges at (charge_rate ?robot) for a
;   duration of the planner's choice, at least 1 and at most the time that
;   fills the battery to (capacity ?robot). A dock charges one robot at a
;   time.
; - A robot holds one remedy at a time: it carries it from where it is and
;   gives it to the senior it is prescribed for, in the senior's room.
(define (domain robot_battery)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types robot senior location remedy - object)

  (:predicates
    (be ?locatable - (either robot senior remedy) ?loc - location)
    (path ?loc1 - location ?loc2 - location)
    (dock_free ?loc - location)         ; a dock is here and no robot uses it
    (hand_empty ?robot - robot)
    (holding ?robot - robot ?item - remedy)
    (prescribed ?item - remedy ?senior - senior)
    (treated ?senior - senior))

  (:functions
    (moving_time ?loc1 - location ?loc2 - location) - number
    (handling_time) - number            ; carry, give
    (battery ?robot - robot) - number
    (capacity ?robot - robot) - number
    (reserve ?robot - robot) - number
    (drain_rate ?robot - robot) - number
    (charge_rate ?robot - robot) - number)

  ;; movement of a robot between two connected locations, draining its battery
  (:durative-action move
    :parameters (?robot - robot ?loc1 - location ?loc2 - location)
    :duration (= ?duration (moving_time ?loc1 ?loc2))
    :condition (and (at start (be ?robot ?loc1))
                    (over all (path ?loc1 ?loc2))
                    (over all (>= (battery ?robot) (reserve ?robot))))
    :effect (and (at start (not (be ?robot ?loc1)))
                 (at end (be ?robot ?loc2))
                 (decrease (battery ?robot) (* #t (drain_rate ?robot)))))

  ;; the robot recharges at a dock for as long as the planner chooses, up to full
  (:durative-action recharge
    :parameters (?robot - robot ?loc - location)
    :duration (and (>= ?duration 1)
                   (<= ?duration (/ (- (capacity ?robot) (battery ?robot)) (charge_rate ?robot))))
    :condition (and (at start (dock_free ?loc))
                    (over all (be ?robot ?loc))
                    (over all (<= (battery ?robot) (capacity ?robot))))
    :effect (and (at start (not (dock_free ?loc)))
                 (at end (dock_free ?loc))
                 (increase (battery ?robot) (* #t (charge_rate ?robot)))))

  ;; the robot picks up a remedy where it is
  (:durative-action carry
    :parameters (?robot - robot ?item - remedy ?location - location)
    :duration (= ?duration (handling_time))
    :condition (and (at start (be ?item ?location))
                    (at start (hand_empty ?robot))
                    (over all (be ?robot ?location)))
    :effect (and (at start (not (be ?item ?location)))
                 (at start (not (hand_empty ?robot)))
                 (at end (holding ?robot ?item))))

  ;; the robot gives a senior the remedy prescribed for them
  (:durative-action give
    :parameters (?robot - robot ?senior - senior ?item - remedy ?location - location)
    :duration (= ?duration (handling_time))
    :condition (and (at start (holding ?robot ?item))
                    (at start (prescribed ?item ?senior))
                    (over all (be ?robot ?location))
                    (over all (be ?senior ?location)))
    :effect (and (at start (not (holding ?robot ?item)))
                 (at end (hand_empty ?robot))
                 (at end (treated ?senior))))
)
