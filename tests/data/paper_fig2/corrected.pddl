; The paper's Fig. 2 as in as_printed.pddl, with its two slips corrected:
; `be` gets the '-' before its (either ...) type, and the head of
; entertainment2_suggested loses the stray `senior`. Fig. 2 gives heads only,
; so the actions still lack their durations (the full domain is in
; domains/assisted_living/).
(define (domain assisted_living_fig2)
(:requirements :typing :durative-actions :timed-initial-literals)
(:types
    robot senior location drinking_vessel making_music - object
    entertainment - object
    solving reading communication_device - entertainment
    drinking_glass glass_bottle - drinking_vessel
    violin guitar - making_music
    puzzle yoyo - solving
    magazine book  - reading
    tv desktop - communication_device
    dinning_room kitchen music_room library bedroom - location
    corridor sunroom - location)

(:predicates
;; locatable is at a location
(be ?locatable - (either robot senior drinking_vessel
    making_music entertainment) ?loc - location)
;; a link exists between two location
(path ?loc1 - location ?loc2 - location)
;; time-window for soothing terrified
(hydration_time ?senior - senior)
;; the senior has fear (terrified)
(terrified ?senior - senior)
;; the senior is sad
(sad ?senior - senior)
;; the senior is bored
(bored ?senior - senior)
;; fear is soothed
(soothed ?senior - senior)
;; sadness is soothed and the person is cheerful
(cheerful ?senior - senior)
;; boredom is soothed and the person is entertained
(entertained ?senior - senior)
;; availability of an object
(available ?object - (either drinking_vessel
    making_music entertainment))
;; status of a drinking vessel
(filled ?item - drinking_vessel)
;; the robot is carrying an object
(holding ?robot - robot ?item - (either drinking_vessel
    making_music solving reading))
;; an object has already been given to a senior
(given ?item - (either drinking_vessel making_music
    solving reading) ?senior - senior)
;; a suggestion has already been given to a senior
(suggested ?item - (either tv desktop) ?senior - senior))

(:functions (moving_time ?loc1 ?loc2 - location))

;; movement of robot between two connected locations
(:durative-action move :parameters (?robot - robot ?loc1 - location ?loc2 - location))
;; the robot carries an item from a location
(:durative-action carry :parameters (?robot - robot ?item - (either drinking_vessel
    making_music solving reading) ?location - location))
;; the robot fills up a drinking vessel in the kitchen
(:durative-action fill :parameters (?robot - robot ?item - drinking_vessel
                    ?location - kitchen))
;; the robot gives a senior an item
(:durative-action give :parameters (?robot - robot ?senior - senior ?item - (either
    drinking_vessel making_music solving reading)
    ?location - location))
;; senior received soothing for fear state
(:durative-action soothed_received :parameters (?senior - senior
    ?item - drinking_vessel))
;; the senior received the cheering up to soothe sadness
(:durative-action cheer_received :parameters (?senior - senior ?item - making_music))
;; the senior received the entertainment to soothe boredom
(:durative-action entertainment1_received :parameters (?senior - senior ?item - (either
    solving reading)))
;; the robot suggest a different course of entertainment
(:durative-action suggest_entertainment2 :parameters (?robot - robot ?senior - senior
    ?item - (either tv desktop) ?location - location))
;; the senior has received the entertainment suggestion
(:durative-action entertainment2_suggested :parameters (?senior - senior
    ?item - (either tv desktop)))
)
