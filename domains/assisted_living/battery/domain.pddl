; The paper's assisted-living domain (../domain.pddl, which stays as it is for
; the paper's Figs. 6-11) with robot batteries (issue 15), for `alplan home
; --battery`. Every action but `move` is the paper's domain's, word for word,
; so goals, repairs and explanations work unchanged; what is new:
;
; - A move drains the robot's battery at (drain_rate ?robot) per second
;   while it runs (PDDL 2.1 linear continuous change), and the battery must
;   stay at or above (reserve ?robot) over all of the move: a robot never
;   plans to run down below its reserve.
; - `recharge`: in a room with a (dock ?loc), a robot charges at
;   (charge_rate ?robot) for as long as the planner chooses, at least 1 s and
;   at most until the battery is full, (capacity ?robot), as in
;   ../../continuous/robot-battery/. A dock has a pad per robot: several may
;   charge at once (the home has one dock; robots queueing at it would make
;   plans wait on each other for no gain in what the study measures).
;
; The paper's domain, as ../domain.pddl describes it:
;
; The assisted-living domain of "A deliberative ambient-intelligence system
; for comforting stressed seniors" (the paper in shared/seed), rebuilt from
; its Fig. 2 heads and its text. Types, predicates and action heads are the
; paper's; conditions, effects, durations and costs are ours, chosen so that
; the plans of Figs. 6-11 come out action for action and time for time.
;
; - A robot comforts a stressed senior: water (a filled drinking vessel) for
;   a terrified one, a music instrument for a sad one, something to solve or
;   read for a bored one, or, as a last resort, a suggestion to use a TV or a
;   desktop. Suggesting costs (total-cost), so the metric prefers giving.
;   The paper suggests only to a bored senior; its Discussion names turning
;   on the TV as a response beyond objects, so ours may also cheer a sad
;   senior by suggesting music on a TV or desktop (cheer_suggested). Fear
;   calls for water: no suggestion soothes a terrified senior.
; - Objects must be (available ...) when the robot takes them: IoT objects
;   report it, and the monitor sees it change.
; - A terrified senior must be soothed while (hydration_time ?s) holds, a sad
;   or bored one cheered or entertained while (comfort_time ?s) holds: the
;   problem ends these windows with timed initial literals.
; - (iot_tagged ?o) marks an object with an IoT tag: it reports its place and
;   availability wherever the robot is; the others are known only once the
;   robot's camera sees them (repair/observation.h). No action reads it.
(define (domain assisted_living)
  (:requirements :typing :durative-actions :fluents :timed-initial-literals :action-costs
                 :continuous-effects :duration-inequalities)
  (:types
    robot senior location drinking_vessel making_music - object
    device - object
    speaker lamp - device
    entertainment - object
    solving reading communication_device - entertainment
    drinking_glass glass_bottle - drinking_vessel
    violin guitar - making_music
    puzzle yoyo - solving
    magazine book - reading
    tv desktop - communication_device
    dinning_room kitchen music_room library bedroom - location
    corridor sunroom - location)

  (:predicates
    (be ?locatable - (either robot senior drinking_vessel making_music entertainment device) ?loc - location)
    (path ?loc1 - location ?loc2 - location)
    (hydration_time ?senior - senior)
    ;; ours: the time window for cheering or entertaining (the paper's
    ;; Discussion: a sad or bored senior can wait longer than a terrified one)
    (comfort_time ?senior - senior)
    (terrified ?senior - senior)
    (sad ?senior - senior)
    (bored ?senior - senior)
    (soothed ?senior - senior)
    (cheerful ?senior - senior)
    (entertained ?senior - senior)
    (available ?object - (either drinking_vessel making_music entertainment))
    (iot_tagged ?object - (either drinking_vessel making_music entertainment))
    (filled ?item - drinking_vessel)
    (holding ?robot - robot ?item - (either drinking_vessel making_music solving reading))
    (given ?item - (either drinking_vessel making_music solving reading) ?senior - senior)
    (suggested ?item - (either tv desktop) ?senior - senior)
    ;; ours: a device of the senior's room has answered their emotion
    (reassured ?senior - senior)
    ;; batteries: a robot recharges where there is a dock
    (dock ?loc - location))

  (:functions
    (moving_time ?loc1 - location ?loc2 - location) - number
    (handling_time) - number      ; carry, fill, give
    (receiving_time) - number     ; the senior takes what is given
    (suggesting_time) - number
    (suggestion_cost) - number
    (total-cost) - number
    ;; batteries, per robot: level, full level, the level no move may go
    ;; below, drain per second of moving, charge per second at a dock
    (battery ?robot - robot) - number
    (capacity ?robot - robot) - number
    (reserve ?robot - robot) - number
    (drain_rate ?robot - robot) - number
    (charge_rate ?robot - robot) - number)

  ;; movement of robot between two connected locations, draining its battery
  (:durative-action move
    :parameters (?robot - robot ?loc1 - location ?loc2 - location)
    :duration (= ?duration (moving_time ?loc1 ?loc2))
    :condition (and (at start (be ?robot ?loc1)) (over all (path ?loc1 ?loc2))
                    (over all (>= (battery ?robot) (reserve ?robot))))
    :effect (and (at start (not (be ?robot ?loc1))) (at end (be ?robot ?loc2))
                 (decrease (battery ?robot) (* #t (drain_rate ?robot)))))

  ;; the robot recharges at a dock for as long as the planner chooses, up to full
  (:durative-action recharge
    :parameters (?robot - robot ?loc - location)
    :duration (and (>= ?duration 1)
                   (<= ?duration (/ (- (capacity ?robot) (battery ?robot)) (charge_rate ?robot))))
    :condition (and (at start (dock ?loc)) (over all (be ?robot ?loc))
                    (over all (<= (battery ?robot) (capacity ?robot))))
    :effect (increase (battery ?robot) (* #t (charge_rate ?robot))))

  ;; the robot carries an item from a location
  (:durative-action carry
    :parameters (?robot - robot ?item - (either drinking_vessel making_music solving reading) ?location - location)
    :duration (= ?duration (handling_time))
    :condition (and (at start (be ?item ?location)) (at start (available ?item)) (over all (be ?robot ?location)))
    :effect (and (at start (not (be ?item ?location))) (at end (holding ?robot ?item))))

  ;; the robot fills up a drinking vessel in the kitchen
  (:durative-action fill
    :parameters (?robot - robot ?item - drinking_vessel ?location - kitchen)
    :duration (= ?duration (handling_time))
    :condition (and (at start (holding ?robot ?item)) (over all (be ?robot ?location)))
    :effect (at end (filled ?item)))

  ;; the robot gives a senior an item
  (:durative-action give
    :parameters (?robot - robot ?senior - senior ?item - (either drinking_vessel making_music solving reading)
                 ?location - location)
    :duration (= ?duration (handling_time))
    :condition (and (at start (holding ?robot ?item)) (over all (be ?robot ?location))
                    (over all (be ?senior ?location)))
    :effect (and (at start (not (holding ?robot ?item))) (at end (given ?item ?senior))))

  ;; senior received soothing for fear state: water, in time
  (:durative-action soothed_received
    :parameters (?senior - senior ?item - drinking_vessel)
    :duration (= ?duration (receiving_time))
    :condition (and (at start (given ?item ?senior)) (at start (filled ?item)) (at start (terrified ?senior))
                    (over all (hydration_time ?senior)))
    :effect (and (at end (not (terrified ?senior))) (at end (soothed ?senior))))

  ;; the senior received the cheering up to soothe sadness
  (:durative-action cheer_received
    :parameters (?senior - senior ?item - making_music)
    :duration (= ?duration (receiving_time))
    :condition (and (at start (given ?item ?senior)) (at start (sad ?senior)) (over all (comfort_time ?senior)))
    :effect (and (at end (not (sad ?senior))) (at end (cheerful ?senior))))

  ;; the senior received the entertainment to soothe boredom
  (:durative-action entertainment1_received
    :parameters (?senior - senior ?item - (either solving reading))
    :duration (= ?duration (receiving_time))
    :condition (and (at start (given ?item ?senior)) (at start (bored ?senior)) (over all (comfort_time ?senior)))
    :effect (and (at end (not (bored ?senior))) (at end (entertained ?senior))))

  ;; the robot suggests a different course of entertainment, where the senior is
  (:durative-action suggest_entertainment2
    :parameters (?robot - robot ?senior - senior ?item - (either tv desktop) ?location - location)
    :duration (= ?duration (suggesting_time))
    :condition (and (at start (available ?item)) (over all (be ?robot ?location)) (over all (be ?senior ?location)))
    :effect (and (at end (suggested ?item ?senior)) (at end (increase (total-cost) (suggestion_cost)))))

  ;; the senior has received the entertainment suggestion
  (:durative-action entertainment2_suggested
    :parameters (?senior - senior ?item - (either tv desktop))
    :duration (= ?duration (receiving_time))
    :condition (and (at start (suggested ?item ?senior)) (at start (bored ?senior)) (over all (comfort_time ?senior)))
    :effect (and (at end (not (bored ?senior))) (at end (entertained ?senior))))

  ;; ours: the sad senior has received a suggestion to listen to music on a
  ;; TV or desktop (the paper's Discussion: responses beyond objects)
  (:durative-action cheer_suggested
    :parameters (?senior - senior ?item - (either tv desktop))
    :duration (= ?duration (receiving_time))
    :condition (and (at start (suggested ?item ?senior)) (at start (sad ?senior)) (over all (comfort_time ?senior)))
    :effect (and (at end (not (sad ?senior))) (at end (cheerful ?senior))))

  ;; ours (the paper's Discussion: responses beyond objects): the home's
  ;; devices answer at once, beside the robots, in the senior's room:
  ;; calming music from a speaker for a terrified senior, warm light for a
  ;; sad one, a programme on the TV for a bored one. Instantaneous: no robot
  ;; and no time taken; the home asks for (reassured ?senior) beside the
  ;; comfort goal when such a device stands where the senior is.
  (:action play_calming_music
    :parameters (?speaker - speaker ?senior - senior ?location - location)
    :precondition (and (be ?speaker ?location) (be ?senior ?location) (terrified ?senior))
    :effect (reassured ?senior))

  (:action warm_the_lights
    :parameters (?lamp - lamp ?senior - senior ?location - location)
    :precondition (and (be ?lamp ?location) (be ?senior ?location) (sad ?senior))
    :effect (reassured ?senior))

  (:action put_on_a_programme
    :parameters (?tv - tv ?senior - senior ?location - location)
    :precondition (and (be ?tv ?location) (be ?senior ?location) (bored ?senior) (available ?tv))
    :effect (reassured ?senior))
)
