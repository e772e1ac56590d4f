(define (domain assisted_living)
  (:requirements :typing :durative-actions :fluents :timed-initial-literals :action-costs)
  (:types
    robot - object
    senior - object
    location - object
    drinking_vessel - object
    making_music - object
    entertainment - object
    solving - entertainment
    reading - entertainment
    communication_device - entertainment
    drinking_glass - drinking_vessel
    glass_bottle - drinking_vessel
    violin - making_music
    guitar - making_music
    puzzle - solving
    yoyo - solving
    magazine - reading
    book - reading
    tv - communication_device
    desktop - communication_device
    dinning_room - location
    kitchen - location
    music_room - location
    library - location
    bedroom - location
    corridor - location
    sunroom - location)
  (:predicates
    (be ?locatable - (either robot senior drinking_vessel making_music entertainment) ?loc - location)
    (path ?loc1 - location ?loc2 - location)
    (hydration_time ?senior - senior)
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
    (suggested ?item - (either tv desktop) ?senior - senior))
  (:functions
    (moving_time ?loc1 - location ?loc2 - location) - number
    (handling_time) - number
    (receiving_time) - number
    (suggesting_time) - number
    (suggestion_cost) - number
    (total-cost) - number)
  (:durative-action move
    :parameters (?robot - robot ?loc1 - location ?loc2 - location)
    :duration (= ?duration (moving_time ?loc1 ?loc2))
    :condition (and
      (at start (be ?robot ?loc1))
      (over all (path ?loc1 ?loc2)))
    :effect (and
      (at start (not (be ?robot ?loc1)))
      (at end (be ?robot ?loc2))))
  (:durative-action carry
    :parameters (?robot - robot ?item - (either drinking_vessel making_music solving reading) ?location - location)
    :duration (= ?duration (handling_time))
    :condition (and
      (at start (be ?item ?location))
      (at start (available ?item))
      (over all (be ?robot ?location)))
    :effect (and
      (at start (not (be ?item ?location)))
      (at end (holding ?robot ?item))))
  (:durative-action fill
    :parameters (?robot - robot ?item - drinking_vessel ?location - kitchen)
    :duration (= ?duration (handling_time))
    :condition (and
      (at start (holding ?robot ?item))
      (over all (be ?robot ?location)))
    :effect (at end (filled ?item)))
  (:durative-action give
    :parameters (?robot - robot ?senior - senior ?item - (either drinking_vessel making_music solving reading) ?location - location)
    :duration (= ?duration (handling_time))
    :condition (and
      (at start (holding ?robot ?item))
      (over all (be ?robot ?location))
      (over all (be ?senior ?location)))
    :effect (and
      (at start (not (holding ?robot ?item)))
      (at end (given ?item ?senior))))
  (:durative-action soothed_received
    :parameters (?senior - senior ?item - drinking_vessel)
    :duration (= ?duration (receiving_time))
    :condition (and
      (at start (given ?item ?senior))
      (at start (filled ?item))
      (at start (terrified ?senior))
      (over all (hydration_time ?senior)))
    :effect (and
      (at end (not (terrified ?senior)))
      (at end (soothed ?senior))))
  (:durative-action cheer_received
    :parameters (?senior - senior ?item - making_music)
    :duration (= ?duration (receiving_time))
    :condition (and
      (at start (given ?item ?senior))
      (at start (sad ?senior))
      (over all (comfort_time ?senior)))
    :effect (and
      (at end (not (sad ?senior)))
      (at end (cheerful ?senior))))
  (:durative-action entertainment1_received
    :parameters (?senior - senior ?item - (either solving reading))
    :duration (= ?duration (receiving_time))
    :condition (and
      (at start (given ?item ?senior))
      (at start (bored ?senior))
      (over all (comfort_time ?senior)))
    :effect (and
      (at end (not (bored ?senior)))
      (at end (entertained ?senior))))
  (:durative-action suggest_entertainment2
    :parameters (?robot - robot ?senior - senior ?item - (either tv desktop) ?location - location)
    :duration (= ?duration (suggesting_time))
    :condition (and
      (at start (available ?item))
      (over all (be ?robot ?location))
      (over all (be ?senior ?location)))
    :effect (and
      (at end (suggested ?item ?senior))
      (at end (increase (total-cost) (suggestion_cost)))))
  (:durative-action entertainment2_suggested
    :parameters (?senior - senior ?item - (either tv desktop))
    :duration (= ?duration (receiving_time))
    :condition (and
      (at start (suggested ?item ?senior))
      (at start (bored ?senior))
      (over all (comfort_time ?senior)))
    :effect (and
      (at end (not (bored ?senior)))
      (at end (entertained ?senior))))
  (:durative-action cheer_suggested
    :parameters (?senior - senior ?item - (either tv desktop))
    :duration (= ?duration (receiving_time))
    :condition (and
      (at start (suggested ?item ?senior))
      (at start (sad ?senior))
      (over all (comfort_time ?senior)))
    :effect (and
      (at end (not (sad ?senior)))
      (at end (cheerful ?senior))))
)
