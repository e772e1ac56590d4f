; Water tanks filled by pumps and drained into fields.
;
; - A pump fills a tank it is piped to, raising the tank's level continuously
;   at the pump's rate for as long as the planner chooses (at most one shift,
;   (pump-shift ?p)); the level must stay at or below the tank's capacity over
;   all of the filling. A pump fills one tank at a time.
; - Irrigating a field drains a tank that feeds it continuously at the
;   field's flow rate, for the field's irrigation time; the level must stay
;   at or above zero over all of the irrigation. A field needs one
;   irrigation; several may draw on one tank at once, and a tank may be
;   filled while it drains (the net rate is the pumps' rates minus the
;   flows).
; - A field may need more water than its tank holds: then the tank must be
;   filled while the field is irrigated.
(define (domain tank)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types tank pump field - object)

  (:predicates
    (pipe ?p - pump ?t - tank)          ; the pump can fill the tank
    (feeds ?t - tank ?f - field)        ; the tank can irrigate the field
    (pump-idle ?p - pump)
    (dry ?f - field)                    ; not irrigated yet
    (watered ?f - field))

  (:functions
    (level ?t - tank) - number
    (capacity ?t - tank) - number
    (pump-rate ?p - pump) - number
    (pump-shift ?p - pump) - number     ; the longest a pump runs at a stretch
    (flow-rate ?f - field) - number
    (irrigation-time ?f - field) - number)

  ;; a pump fills a tank for a duration of the planner's choice
  (:durative-action fill
    :parameters (?p - pump ?t - tank)
    :duration (and (>= ?duration 1) (<= ?duration (pump-shift ?p)))
    :condition (and (at start (pipe ?p ?t))
                    (at start (pump-idle ?p))
                    (over all (<= (level ?t) (capacity ?t))))
    :effect (and (at start (not (pump-idle ?p)))
                 (at end (pump-idle ?p))
                 (increase (level ?t) (* #t (pump-rate ?p)))))

  ;; a tank irrigates a field: the field's flow for the field's time
  (:durative-action irrigate
    :parameters (?t - tank ?f - field)
    :duration (= ?duration (irrigation-time ?f))
    :condition (and (at start (feeds ?t ?f))
                    (at start (dry ?f))
                    (over all (>= (level ?t) 0)))
    :effect (and (at start (not (dry ?f)))
                 (at end (watered ?f))
                 (decrease (level ?t) (* #t (flow-rate ?f)))))
)
